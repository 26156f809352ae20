# Pendulab: `make run` starts the lab (web server + browser page), `make test` runs every test suite
# (CI calls it). Everything Python lives in a local virtual environment .venv (created on first use);
# the web front end's Node packages in web/node_modules (npm ci, from web/package-lock.json).

PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
SCENARIO ?= examples/scenarios/rosette.toml
HOST ?= 127.0.0.1
PORT ?= 8000
STATIC := python/pendulab/server/static

# `make` alone builds the package into .venv (see build below).
.DEFAULT_GOAL := build

.PHONY: run simulate serve web test build venv lint lint-stubs fmt test-rust test-python test-tour test-web test-e2e bench \
	bench-compare bench-peers bench-fit validate-fit golden clean fuzz docs docs-serve bench-portable wheel test-wheel \
	bench-peers-portable bench-roofline check-aarch64 wasm test-wasm lab-html test-lab-html bench-wasm bench-lab-html test-lab-firefox test-tour-wheel \
	bench-instructions

$(VENV)/.deps: python/pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet "maturin>=1.7,<2" "numpy>=1.26" "typer>=0.29" "tqdm>=4.66" "pydantic>=2.6" \
		"pytest>=8" "ruff>=0.5" "mpmath>=1.3" "sympy>=1.12" "scipy>=1.11" "threadpoolctl>=3.1" "pyarrow>=15" "xarray>=2024.1" "pandas>=2" "zarr>=2.18" "matplotlib>=3.8" \
		"fastapi>=0.115" "uvicorn>=0.30" "websockets>=13" "orjson>=3.10" "qrcode>=8" "httpx>=0.27" "httpx2>=2" "dask[distributed]>=2024.1" \
		"imageio-ffmpeg>=0.5" "pillow>=10.1" "nbclient>=0.10" "nbformat>=5.10" "ipykernel>=6.29" \
		"ziglang>=0.13" "auditwheel>=6" \
		"hypothesis>=6.100" \
		"mypy>=1.20,<2" "scipy-stubs>=1.15" "types-tqdm>=4.66" "types-qrcode>=8"
	touch $@

venv: $(VENV)/.deps

# The documentation site's tools, in the same .venv (the API reference, the CLI reference and the
# gallery import pendulab). Keep in step with the "docs" extra of python/pyproject.toml.
$(VENV)/.docs-deps: $(VENV)/.deps
	$(PY) -m pip install --quiet "mkdocs>=1.6" "mkdocs-material>=9.5" "mkdocstrings[python]>=0.26" \
		"mkdocs-jupyter>=0.25" "jupyter-server-mathjax>=0.2.6"
	touch $@

# The core is compiled for the baseline of the CPU architecture (x86-64: SSE2); its hot loops pick
# AVX2 + FMA or AVX-512 at run time (crates/pendulab-core/src/isa.rs), so a build runs on any CPU of its
# kind. RUSTFLAGS="-C target-cpu=native" make build gives a build for this machine only (docs/performance.md).
# BUILD_PROFILE: the Cargo profile, release (link-time optimised) for the lab and the benchmarks; `make test`
# builds with test-opt (Cargo.toml: the same numbers bit for bit, no link-time optimisation), which the Rust
# tests then reuse; the wheel that test-wheel installs is a release build.
BUILD_PROFILE ?= release
build: venv
	VIRTUAL_ENV=$(CURDIR)/$(VENV) $(VENV)/bin/maturin develop --profile $(BUILD_PROFILE) --quiet -m python/Cargo.toml
	@echo "built: run '. $(VENV)/bin/activate' for 'pendulab' and 'import pendulab' in this shell, or use $(VENV)/bin/pendulab"

# A wheel for other machines and an sdist, in dist/ (README "Install"): abi3 (CPython >= 3.11),
# manylinux2014 (glibc >= 2.17; linked by zig from PyPI's ziglang), the baseline CPU with run-time
# AVX2/AVX-512 dispatch; checked with auditwheel. `pip install "$$(ls dist/pendulab-*.whl)[lab]"` (README.md, Install).
wheel: venv
	rm -rf dist
	PATH="$(CURDIR)/$(VENV)/bin:$$PATH" $(VENV)/bin/maturin build --release --quiet -m python/Cargo.toml \
		--compatibility manylinux2014 --zig --interpreter $(PY) -o dist
	$(VENV)/bin/maturin sdist -m python/Cargo.toml -o dist
	$(VENV)/bin/auditwheel show dist/pendulab-*.whl | tee dist/.auditwheel
	grep -q '"manylinux_2_17_$(shell uname -m)"' dist/.auditwheel
	@ls -l dist

# The wheel as a user gets it: a fresh virtual environment outside the checkout, the README quickstart,
# pendulab scenarios / run / serve (page + WebSocket), and an old CPU under qemu-user if installed.
test-wheel: wheel
	$(PYTHON) tools/check_wheel.py dist

# The lab: builds the core, the Python package and the web bundle, then serves SCENARIO at
# http://$(HOST):$(PORT) (opens a browser where there is one; Ctrl-C stops it).
run: build web
	$(VENV)/bin/pendulab serve $(SCENARIO) --host $(HOST) --port $(PORT)

# The lab with the web bundle already in the package (no Node needed).
serve: build
	$(VENV)/bin/pendulab serve $(SCENARIO) --host $(HOST) --port $(PORT)

# A batch run of SCENARIO without the browser: prints a summary, writes rosette.csv.
simulate: build
	$(VENV)/bin/pendulab run $(SCENARIO) --out rosette.csv

# The web front end: npm ci (only when the lock file changed), type check + Vite build, and the bundle
# copied into the Python package ($(STATIC), committed so that the package alone serves the lab).
web/node_modules/.package-lock.json: web/package.json web/package-lock.json
	cd web && npm ci --no-audit --no-fund
	touch $@

web: web/node_modules/.package-lock.json
	cd web && npm run build
	rm -rf $(STATIC)
	cp -r web/dist $(STATIC)

test-web: web/node_modules/.package-lock.json
	cd web && node_modules/.bin/tsc --noEmit
	cd web && node_modules/.bin/eslint src   # max-lines-per-function (web/eslint.config.mjs)
	cd web && node_modules/.bin/vitest run

# The lab end to end, once per transport: `pendulab serve` on a free port with the committed bundle, then
# the one-file lab (dist/pendulab-lab.html) from file:// with every network request refused, the same
# checks in Debian's headless chromium (web/tests/e2e/run.sh; needs `apt-get install chromium`, which
# .ci/run does). Screenshots and the measured frame rate: web/test-results/.
test-e2e: build web/node_modules/.package-lock.json lab-html
	bash web/tests/e2e/run.sh

lint: venv
	cargo fmt --all -- --check
	cargo clippy --workspace --all-targets -- -D warnings
	$(VENV)/bin/ruff check python bench testdata/generate tools docs/gallery
	$(VENV)/bin/ruff format --check python bench testdata/generate tools docs/gallery
	$(VENV)/bin/mypy --config-file python/pyproject.toml   # the package's hints and _core.pyi ([tool.mypy])
	$(PY) tools/check_imports.py
	$(PY) tools/check_rust_modules.py crates/pendulab-core/src
	$(PY) tools/check_rust_modules.py python/rust
	$(PY) tools/check_rust_modules.py crates/pendulab-wasm/src
	$(PY) tools/check_file_length.py   # at most 400 lines per source file (ARCHITECTURE.md, "File length")
	RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps --quiet

# The hand-written stub of the compiled core, python/pendulab/_core.pyi, against the core itself (mypy's
# stubtest on the built module: every binding of python/rust/*.rs in the stub with the same parameter
# names, kinds and defaults, nothing in the stub that the core lacks; the exceptions, stub-only types,
# in python/stubtest-allowlist.txt). Needs the build, so it is apart from lint; `make test` runs both.
lint-stubs: build
	$(PY) -m mypy.stubtest pendulab._core --mypy-config-file python/pyproject.toml --ignore-disjoint-bases \
		--allowlist python/stubtest-allowlist.txt

fmt: venv
	cargo fmt --all
	$(VENV)/bin/ruff format python bench testdata/generate tools docs/gallery
	$(VENV)/bin/ruff check --fix python bench testdata/generate tools docs/gallery

# The core's tests (its unit tests, and tests/suite.rs: every file of crates/pendulab-core/tests as one test
# binary) in the test-opt profile: optimised like release, without its link-time optimisation (Cargo.toml).
# --tests: the examples are not built here (clippy --all-targets in lint checks that they compile).
test-rust:
	cargo test --profile test-opt -p pendulab-core --tests

# The lab's engine as WebAssembly (crates/pendulab-wasm, plain C ABI; docs/lab.md): needs the target,
# `rustup target add wasm32-unknown-unknown` (.ci/run installs it). Two builds of the same code: with
# SIMD128 (every browser since Chrome 91, Firefox 89, Safari 16.4; the page takes it when
# WebAssembly.validate accepts a SIMD instruction) and without (the fallback), each in its own target
# directory, then `wasm-opt -O3` (Debian's binaryen; without it the builds are kept unoptimised, with a
# warning; run again when cargo wrote a newer build or the optimiser changed: each .wasm has a
# `.wasm.opt` beside it naming how it was made, so a build copied unoptimised before binaryen was
# installed is optimised on the next `make wasm`). Both compute the native build's numbers bit for bit
# (make test-wasm; docs/performance.md).
WASM := target/wasm/pendulab-wasm.wasm
WASM_SIMD := target/wasm/pendulab-wasm-simd128.wasm
WASM_OPT ?= $(shell command -v wasm-opt)
wasm:
	@rustc --print target-libdir --target wasm32-unknown-unknown >/dev/null 2>&1 && \
		test -d "$$(rustc --print target-libdir --target wasm32-unknown-unknown)" || { \
		echo "error: the Rust target wasm32-unknown-unknown is not installed: run 'rustup target add wasm32-unknown-unknown'" >&2; exit 1; }
	@# the two builds side by side (each links the whole engine in one codegen unit: one core each)
	cargo build --profile wasm --target wasm32-unknown-unknown -p pendulab-wasm & plain=$$!; \
		CARGO_TARGET_DIR=$(CURDIR)/target/wasm-simd128 CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-C target-feature=+simd128" \
		cargo build --profile wasm --target wasm32-unknown-unknown -p pendulab-wasm & simd=$$!; \
		wait $$plain; a=$$?; wait $$simd; b=$$?; test $$a -eq 0 && test $$b -eq 0
	@mkdir -p target/wasm
	@set -e; pids=""; if [ -n "$(WASM_OPT)" ]; then how="$$($(WASM_OPT) --version) -O3"; else how=unoptimised; fi; \
		for pair in target/wasm32-unknown-unknown/wasm/pendulab_wasm.wasm:$(WASM) \
		target/wasm-simd128/wasm32-unknown-unknown/wasm/pendulab_wasm.wasm:$(WASM_SIMD); do \
		src=$${pair%%:*}; dst=$${pair#*:}; \
		if [ "$$dst" -nt "$$src" ] && [ "$$(cat $$dst.opt 2>/dev/null)" = "$$how" ]; then continue; fi; \
		( set -e; if [ -n "$(WASM_OPT)" ]; then echo "wasm-opt -O3 $$src -> $$dst"; $(WASM_OPT) -O3 $$src -o $$dst.tmp; \
		else echo "warning: wasm-opt not found (apt-get install binaryen): $$dst is not optimised (slower)" >&2; cp $$src $$dst.tmp; fi; \
		rm -f $$dst.opt; mv $$dst.tmp $$dst; echo "$$how" > $$dst.opt ) & pids="$$pids $$!"; done; \
		for pid in $$pids; do wait $$pid; done
	@ls -l $(WASM) $(WASM_SIMD)

# The lab with nothing to install (docs/lab.md): one HTML file with the engine (.wasm: raw DEFLATE, base64), its Web
# Worker (a Blob URL), the schema and example scenarios (tools/lab_snapshot.py: the server's answers),
# scripts and styles inlined; opens from file:// with no network. At most 3 MB.
LAB_HTML := dist/pendulab-lab.html
lab-html: build wasm web/node_modules/.package-lock.json
	mkdir -p target dist
	$(PY) tools/lab_snapshot.py target/lab-snapshot.json
	cd web && PENDULAB_WASM=../$(WASM) PENDULAB_WASM_SIMD=../$(WASM_SIMD) PENDULAB_LAB_SNAPSHOT=../target/lab-snapshot.json LAB_OUT_DIR=../target/lab-html \
		node_modules/.bin/vite build -c vite.lab.config.mjs --logLevel warn
	cp target/lab-html/index.html $(LAB_HTML).tmp && mv $(LAB_HTML).tmp $(LAB_HTML)
	@size=$$(stat -c %s $(LAB_HTML)); echo "$(LAB_HTML): $$size bytes"; \
		if [ "$$size" -gt 3000000 ]; then echo "error: $(LAB_HTML) is $$size bytes, over the 3 MB (3,000,000 bytes) budget" >&2; exit 1; fi

# The one-file lab end to end: opened from file:// in headless chromium with every network request
# refused (web/tests/e2e/lab_file.mjs; docs/lab.md). Screenshot: web/test-results/lab-file.png.
test-lab-html: lab-html
	cd web && CHROMIUM=$${CHROMIUM:-$$(command -v chromium || command -v chromium-browser)} \
		node tests/e2e/lab_file.mjs $(CURDIR)/$(LAB_HTML)

# The one-file lab's first frame and frame rate with the error estimate on, in headless chromium from
# file:// (bench/lab_frames.mjs; docs/performance.md; say the load), beside baselines (a blank page, a bare
# three.js scene) in the same run, with CPU time per frame by thread. About 1.5 minutes.
bench-lab-html: lab-html
	CHROMIUM=$${CHROMIUM:-$$(command -v chromium || command -v chromium-browser)} node bench/lab_frames.mjs $(LAB_HTML)

# The one-file lab in Firefox (optional, not in CI: docs/web.md, "Firefox"): Debian's firefox-esr
# (apt-get install firefox-esr) driven by geckodriver (cargo install geckodriver: a few minutes of
# compiling) over W3C WebDriver, from file:// with no network, on a virtual display (apt-get install
# xvfb; headless Firefox gets no WebGL here): first frame, frames, a refusal, a share link.
test-lab-firefox: lab-html
	@command -v $${FIREFOX:-firefox-esr} >/dev/null || { echo "error: firefox-esr not found: apt-get install firefox-esr (or FIREFOX=/path)" >&2; exit 1; }
	@command -v $${GECKODRIVER:-geckodriver} >/dev/null || { echo "error: geckodriver not found: cargo install geckodriver (or GECKODRIVER=/path)" >&2; exit 1; }
	@test -n "$$DISPLAY" || command -v xvfb-run >/dev/null || { echo "error: no DISPLAY and no xvfb-run: apt-get install xvfb" >&2; exit 1; }
	cd web && $(if $(DISPLAY),,xvfb-run -a -s "-screen 0 1280x800x24") node tests/e2e/lab_firefox.mjs $(CURDIR)/$(LAB_HTML)

# RATTLE steps/s of the engine in node beside the native build (docs/performance.md; say the load):
# both .wasm builds and the native one in BENCH_WASM_ROUNDS interleaved rounds, timed by CPU time.
BENCH_WASM_ROUNDS ?= 9
bench-wasm: wasm
	cargo build --release -p pendulab-wasm --example trajectory
	node bench/wasm_steps.mjs target/release/examples/trajectory $(WASM_SIMD) $(WASM) --rounds $(BENCH_WASM_ROUNDS)

# The engine's tests: natively (cargo test), then the .wasm in node against the native build's
# trajectories of every lab model and method (bit for bit, or 1e-12 l where libm differs).
test-wasm: wasm
	cargo test --profile test-opt -p pendulab-wasm
	cargo build --profile test-opt -p pendulab-wasm --example trajectory
	node crates/pendulab-wasm/tests/parity.mjs $(WASM_SIMD) target/test-opt/examples/trajectory
	node crates/pendulab-wasm/tests/parity.mjs $(WASM) target/test-opt/examples/trajectory

# PYTEST_ARGS: `make test` leaves out the tour's runs in .venv (test-tour-wheel runs them as a user would).
test-python: build
	$(VENV)/bin/pytest python/tests -q --durations=15 $(PYTEST_ARGS)

# The guided tour alone (docs/tour/*.ipynb run by nbclient in .venv; also part of test-python): 70 s to 2 min.
test-tour: build
	$(VENV)/bin/pytest python/tests/test_tour.py -q

# The guided tour as a user runs it (issue 31): the wheel installed with the `tour` extra by the README's
# line in a fresh environment outside the checkout, every notebook run there, each within 20 s
# (TOUR_LIMIT; a slower one fails with its name and time): tools/check_tour.py. `make test` runs it
# instead of the tour's runs in .venv.
TOUR_LIMIT ?= 20
test-tour-wheel: wheel
	$(PYTHON) tools/check_tour.py dist --limit $(TOUR_LIMIT)

# The documentation site (mkdocs.yml, hooks in tools/docs_site.py) into site/, strict: a broken link,
# a missing API entry, a failing gallery script or notebook, or a page that loads anything from the
# network fails it. Open site/index.html (no server needed). `make docs-serve`: live at
# http://127.0.0.1:8001 (gallery and notebook results cached in target/docs-gallery/, docs-notebooks/).
# The guided tour's notebooks are run while the site is built (DOCS_EXECUTE=false: rendered without
# outputs); `make test` runs them once, in test-python (test_tour.py), and builds the site without.
DOCS_EXECUTE ?= true
docs: build $(VENV)/.docs-deps lab-html
	rm -rf target/docs-gallery target/docs-notebooks
	PENDULAB_DOCS_EXECUTE=$(DOCS_EXECUTE) $(VENV)/bin/mkdocs build --strict --clean

docs-serve: build $(VENV)/.docs-deps lab-html
	$(VENV)/bin/mkdocs serve --strict -a 127.0.0.1:8001

test: DOCS_EXECUTE := false
test: BUILD_PROFILE := test-opt
test: PYTEST_ARGS := --deselect python/tests/test_tour.py::test_notebook_runs
test: lint lint-stubs test-rust test-wasm test-python test-web test-e2e test-lab-html docs test-wheel test-tour-wheel

# Hostile input, long (docs/limits.md, "Fuzzing"): FUZZ_CASES generated inputs per entry point of the
# Python API (hypothesis) and of the Rust core (proptest), and the whole corpus of FUZZ_FILES mutated
# scenario files through `pendulab validate` and `pendulab run`; then the exact solution's degenerate
# starts (docs/exact.md: FUZZ_CASES per family in Rust, 1000 per family in Python). CI runs the same
# tests with 25-256 cases and 80 files. Prints the counts; about an hour on 2 free cores at the defaults.
FUZZ_CASES ?= 10000
FUZZ_FILES ?= 2500
fuzz: build
	PROPTEST_CASES=$(FUZZ_CASES) cargo test --profile test-opt -p pendulab-core --test suite fuzz_props:: -- --nocapture
	FUZZ_EXAMPLES=$(FUZZ_CASES) $(VENV)/bin/pytest python/tests/test_fuzz_api.py python/tests/test_fuzz_api_derived.py -q -s
	$(PY) tools/fuzz_scenarios.py --files $(FUZZ_FILES) --seed 13
	PROPTEST_CASES=$(FUZZ_CASES) cargo test --profile test-opt -p pendulab-core --test suite exact_degenerate::
	PENDULAB_LONG=1 $(VENV)/bin/pytest python/tests/test_exact_degenerate.py -q

bench:
	cargo bench -p pendulab-core

# The portable build against one for this CPU only (-C target-cpu=native), criterion benches run
# alternately in one run (about 10 min): docs/performance.md "Portable builds". PORTABLE_ARGS="--reference
# DIR" compares with another checkout instead (e.g. a worktree of the commit before a change).
PORTABLE_ARGS ?=
bench-portable:
	$(PYTHON) bench/portable.py $(PORTABLE_ARGS)

# The peers benchmark's full scans (Pendulab and the C baselines) for the portable wheel and a wheel
# for this CPU only (-C target-cpu=native), run alternately (about 45 min): docs/performance.md
# "Portable builds". PEERS_PORTABLE_ARGS="--rounds 3" for more rounds.
PEERS_PORTABLE_ARGS ?=
bench-peers-portable: build
	$(PY) bench/peers/native_vs_portable.py $(PEERS_PORTABLE_ARGS)

# The core type-checked for aarch64 (clippy -D warnings; needs the target's standard library:
# `rustup target add aarch64-unknown-linux-gnu`, which .ci/run does): x86-only code stays behind cfg.
check-aarch64:
	CARGO_TARGET_DIR=$(CURDIR)/target/check-aarch64 cargo clippy -p pendulab-core \
		--target aarch64-unknown-linux-gnu --all-targets -- -D warnings

# The machine's roof (FMA per vector width, triad bandwidth) and the hot kernels on it (issue 29):
# bench/roofline/results/roofline.json, docs/img/roofline.png, docs/performance.md "How fast, and why".
bench-roofline: build
	$(PY) bench/roofline/run.py $(ROOFLINE_ARGS)

# Instructions (and simulated cache misses) of the hot paths at the commit before issue 25's work and
# at HEAD, counted by valgrind's cachegrind: a check that the machine's load cannot disturb
# (docs/performance.md, "Instruction counts"; BENCH_INSTRUCTIONS_ARGS="--base REV --new REV --baseline").
# Builds both commits below target/instructions the first time (about 15 min), then about 3 min.
bench-instructions: venv
	@command -v valgrind >/dev/null || { echo "bench-instructions needs valgrind (apt-get install valgrind)"; exit 1; }
	$(PY) bench/instructions.py $(BENCH_INSTRUCTIONS_ARGS)

bench-compare: build
	$(PY) bench/compare.py

# Pendulab against its peers (SciPy, numba, C, MuJoCo, JAX + Diffrax): a separate virtual environment
# bench/peers/.venv with the peers and a release wheel of this checkout's Pendulab (not the editable
# build of .venv), then bench/peers/run.py: results/, docs/img/peers_work_precision.png and the
# "Against peers" section of docs/performance.md (about 20 min; PEERS_ARGS=--quick for a smoke run).
# The wheel is the portable build (baseline CPU, hot loops dispatched at run time: crates/pendulab-core/
# src/isa.rs); PEERS_RUSTFLAGS="..." sets RUSTFLAGS for it (in its own target directory, so the default
# build's cache is kept), e.g. PEERS_RUSTFLAGS="-C target-cpu=native" for a build for this CPU only,
# like the C baselines' -march=native.
PEERS_VENV := bench/peers/.venv
PEERS_ARGS ?=
PEERS_RUSTFLAGS ?=

$(PEERS_VENV)/.deps: bench/peers/requirements.txt
	$(PYTHON) -m venv $(PEERS_VENV)
	$(PEERS_VENV)/bin/python -m pip install --quiet --upgrade pip
	$(PEERS_VENV)/bin/python -m pip install --quiet -r bench/peers/requirements.txt
	touch $@

bench-peers: $(PEERS_VENV)/.deps
	rm -rf bench/peers/build/wheels
	$(if $(PEERS_RUSTFLAGS),RUSTFLAGS="$(PEERS_RUSTFLAGS)" CARGO_TARGET_DIR=$(CURDIR)/target/peers-rustflags,) \
		$(PEERS_VENV)/bin/maturin build --release --quiet -m python/Cargo.toml \
		--interpreter $(PEERS_VENV)/bin/python -o bench/peers/build/wheels
	$(PEERS_VENV)/bin/python -m pip install --quiet --force-reinstall --no-deps bench/peers/build/wheels/pendulab-*.whl
	PEERS_RUSTFLAGS="$(PEERS_RUSTFLAGS)" $(PEERS_VENV)/bin/python bench/peers/run.py $(PEERS_ARGS)

# pl.fit with sigma left out on independent data: 40 seeded trials per case, right/wrong model, degenerate
# data (docs/fit.md, Validation; bench/fit_validate.py --quick: 4 trials per case)
validate-fit: build
	$(PY) bench/fit_validate.py

# pl.fit's speed: 10^4 samples over 60 s, 5 unknowns (docs/performance.md)
bench-fit: build
	$(PY) bench/fit_speed.py

golden: venv
	$(PY) testdata/generate/golden_states.py

clean:
	cargo clean
	rm -rf $(VENV)
