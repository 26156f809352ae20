// The page's REST requests when the physics runs in the page (docs/lab.md): GET api/schema and
// api/scenarios are answered from what the one-file lab carries (the server's answers when the file was
// built); what needs Python — the fit of a data file, the analyses computed by the server (the exact
// solution's quantities, V_eff, the energy–momentum map, the reduced view), the scenario as TOML — is
// answered 501 with a message saying so, which the panels show.
import type { LabBundle } from './index';

/** The message of a request that needs the server. */
export function needsServer(what: string): string {
  return `${what} needs the Python server: install pendulab and run 'pendulab serve' (this page computes the motion itself, in the browser)`;
}

const WHAT: Record<string, string> = {
  'api/fit': 'fitting a data file',
  'api/exact': 'the exact solution’s quantities',
  'api/effective_potential': 'V_eff',
  'api/em_map': 'the energy–momentum map',
  'api/reduced': 'the reduced view',
  'api/scenario.toml': 'the scenario as a TOML file',
};

/** The answer to `path` (relative, "api/…") in the page, or null when it is not an API path. */
export function answer(path: string, lab: LabBundle): Response | null {
  const p = path.replace(/^\.?\//, '').split('?')[0] ?? '';
  if (!p.startsWith('api/')) return null;
  const json = (body: unknown, status = 200) =>
    new Response(JSON.stringify(body), { status, headers: { 'content-type': 'application/json' } });
  if (p === 'api/schema') return json(lab.schema);
  if (p === 'api/scenarios') return json(lab.scenarios);
  return json({ detail: needsServer(WHAT[p] ?? p) }, 501);
}

/** Routes the page's fetches of api/… to `answer`; everything else goes to the browser's fetch. */
export function installApi(lab: LabBundle): void {
  const fetchFromNetwork = window.fetch.bind(window);
  window.fetch = (input: RequestInfo | URL, init?: RequestInit) => {
    const url = typeof input === 'string' ? input : input instanceof URL ? input.href : input.url;
    const local = answer(url, lab);
    return local !== null ? Promise.resolve(local) : fetchFromNetwork(input, init);
  };
}
