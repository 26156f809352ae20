// The settings panel (panels/controls.ts, lil-gui) wired to the session and the exports: the CSV of the
// run (SI columns), the scenario as TOML (from the server, api/scenario.toml), a PNG of the view and the
// share link (which says what it carries).
import { Controls } from '../panels/controls';
import type { ScenarioInfo, Schema } from '../protocol';
import { scenarioRequest } from '../export';
import { linkContents } from '../url';
import { httpProblem, t } from '../i18n';
import { byId, download, downloadBlob } from './page';
import type { SharedLink } from './link';
import type { LabCore } from './session';

/** Asks the server for the shown scenario as TOML and saves it. */
function downloadTOML(lab: LabCore): void {
  const s = lab.store.status;
  if (s === null) return lab.explain(t('msg.notConnected'));
  fetch('api/scenario.toml', {
    method: 'POST',
    headers: { 'content-type': 'application/json' },
    body: JSON.stringify(scenarioRequest(s)),
  })
    .then(async (r) => {
      if (!r.ok) throw new Error(httpProblem(await r.json().catch(() => ({})), `HTTP ${r.status}`));
      downloadBlob(`pendulab-${s.scenario ?? 'lab'}.toml`, await r.blob());
    })
    .catch((e: unknown) => lab.explain(t('msg.downloadFailed', { why: e instanceof Error ? e.message : String(e) })));
}

/** Writes the link into the address bar and copies it, saying what it carries. */
function copyLink(lab: LabCore, link: SharedLink): void {
  link.write();
  const href = window.location.href;
  const what = linkContents(link.lab());
  const shown = () => lab.explain(`${href} — ${what}`, true);
  const copied = navigator.clipboard?.writeText(href);
  if (copied === undefined) shown();
  else copied.then(() => lab.explain(t('msg.linkCopied', { what }), true), shown);
}

export function wireControls(lab: LabCore, schema: Schema, scenarios: ScenarioInfo[], link: SharedLink): Controls {
  const { store, scene, view, session, explain } = lab;
  const name = (ext: string) => `pendulab-${store.status?.scenario ?? 'lab'}.${ext}`;
  return new Controls(byId('gui'), schema, scenarios, view, {
    send: session.send,
    explain,
    downloadCSV: () => downloadBlob(name('csv'), new Blob([store.toCSV()], { type: 'text/csv' })),
    downloadTOML: () => downloadTOML(lab),
    screenshot: () => download(name('png'), scene.screenshot()),
    copyLink: () => copyLink(lab, link),
    viewChanged: (v, top) => {
      scene.setTopView(top);
      scene.setStereo(v.stereo);
    },
  });
}
