# Pendulab: `make run` runs the default scenario, `make test` runs every test suite (CI calls it).
# Everything Python lives in a local virtual environment .venv (created on first use).

PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
SCENARIO ?= examples/scenarios/rosette.toml

.PHONY: run test build venv lint fmt test-rust test-python bench bench-compare golden clean

$(VENV)/.deps: python/pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip
	$(PY) -m pip install --quiet "maturin>=1.7,<2" "numpy>=1.26" "typer>=0.12" "tqdm>=4.66" "pydantic>=2.6" \
		"pytest>=8" "ruff>=0.5" "mpmath>=1.3" "scipy>=1.11" "pyarrow>=15" "xarray>=2024.1" "matplotlib>=3.8"
	touch $@

venv: $(VENV)/.deps

build: venv
	VIRTUAL_ENV=$(CURDIR)/$(VENV) $(VENV)/bin/maturin develop --release --quiet -m python/Cargo.toml

run: build
	$(VENV)/bin/pendulab run $(SCENARIO) --out rosette.csv

lint: venv
	cargo fmt --all -- --check
	cargo clippy --workspace --all-targets -- -D warnings
	$(VENV)/bin/ruff check python bench testdata/generate tools
	$(VENV)/bin/ruff format --check python bench testdata/generate tools

fmt: venv
	cargo fmt --all
	$(VENV)/bin/ruff format python bench testdata/generate tools
	$(VENV)/bin/ruff check --fix python bench testdata/generate tools

test-rust:
	cargo test --release -p pendulab-core

test-python: build
	$(VENV)/bin/pytest python/tests -q

test: lint test-rust test-python

bench:
	cargo bench -p pendulab-core

bench-compare: build
	$(PY) bench/compare.py

golden: venv
	$(PY) testdata/generate/golden_states.py

clean:
	cargo clean
	rm -rf $(VENV)
