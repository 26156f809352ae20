// The page's REST requests when the physics runs in the page (docs/lab.md): GET api/schema and
// api/scenarios are answered from what the one-file lab carries (the server's answers when the file was
// built); POST api/exact, api/effective_potential, api/em_map and api/reduced by the core in the page
// (an Engine on this thread: bounded computations, a few ms); what needs Python — the fit of a data file,
// the scenario as a TOML file — is answered 501 with a message saying so, which the panels show.
import type { LabBundle } from './index';
import type { Engine } from './wasm';

/** The requests the core answers in the page. */
export const IN_PAGE = ['api/exact', 'api/effective_potential', 'api/em_map', 'api/reduced'];

/** The message of a request that needs the server. */
export function needsServer(what: string): string {
  return `${what} needs the Python server: install pendulab and run 'pendulab serve' (this page computes the motion itself, in the browser)`;
}

const WHAT: Record<string, string> = {
  'api/fit': 'fitting a data file',
  'api/scenario.toml': 'the scenario as a TOML file',
};

/** The answer to `path` (relative, "api/…") in the page, or null when it is not an API path; `engine`
 *  computes what the core answers in the page (`body`: the request's JSON text). */
export function answer(path: string, lab: LabBundle, engine?: Engine, body?: string): Response | null {
  const p = path.replace(/^\.?\//, '').split('?')[0] ?? '';
  if (!p.startsWith('api/')) return null;
  const json = (body: unknown, status = 200) =>
    new Response(JSON.stringify(body), { status, headers: { 'content-type': 'application/json' } });
  if (p === 'api/schema') return json(lab.schema);
  if (p === 'api/scenarios') return json(lab.scenarios);
  if (engine !== undefined && IN_PAGE.includes(p)) {
    let request: unknown;
    try {
      request = JSON.parse(body ?? '{}');
    } catch {
      return json({ detail: 'the request body is not JSON' }, 422);
    }
    const r = engine.request(p, request);
    return json(r.body, r.status);
  }
  return json({ detail: needsServer(WHAT[p] ?? p) }, 501);
}

/** Routes the page's fetches of api/… to `answer`; everything else goes to the browser's fetch. */
export function installApi(lab: LabBundle, engine: Engine): void {
  const fetchFromNetwork = window.fetch.bind(window);
  window.fetch = (input: RequestInfo | URL, init?: RequestInit) => {
    const url = typeof input === 'string' ? input : input instanceof URL ? input.href : input.url;
    const local = answer(url, lab, engine, typeof init?.body === 'string' ? init.body : undefined);
    return local !== null ? Promise.resolve(local) : fetchFromNetwork(input, init);
  };
}
