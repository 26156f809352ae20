// The toolbar over the view (panels/toolbar.ts) wired to the session, the video recorder, the help
// overlay, the language switch (a reload from the URL once the server has caught up) and the
// presentation mode. Recorded videos are WebM, sizes in bytes.
import { whenCaughtUp } from '../connection';
import { computationsIdle } from '../analyses';
import { HelpOverlay } from '../panels/help';
import { Toolbar } from '../panels/toolbar';
import { Recorder } from '../record';
import { t } from '../i18n';
import { byId, downloadBlob } from './page';
import type { LabCore } from './session';

export interface ToolbarParts {
  toolbar: Toolbar;
  help: HelpOverlay;
  /** The last recorded video's size [bytes] and first four bytes (hex), once a recording stopped. */
  lastVideo: () => { size: number; head: string } | null;
}

/** Reloads the page in language `l` once the server has handled every command sent (≤ 2 s), so that
 *  one just sent — a resume, a fitted scenario — is in the URL the page reloads from. */
function switchLanguage(lab: LabCore, l: string): void {
  window.localStorage?.setItem('pendulab.lang', l);
  const caughtUp = whenCaughtUp(() => lab.store.status?.commands, () => lab.session.sent(), 2000);
  void Promise.all([caughtUp, computationsIdle(2000)]).then(() => {
    const q = new URLSearchParams(window.location.search);
    q.set('lang', l);
    window.location.search = q.toString();
  });
}

/** Where the choice of the simple or the advanced view is remembered on this device (localStorage). */
const SIMPLE_KEY = 'pendulab.simple';

/** The view this device chose last: the simple one ('1'), the advanced one ('0'), or `fallback` (the
 *  default: the simple view) when it never chose or storage is unavailable. A link that says `simple` or
 *  `-simple` overrides it (wiring/link.ts). */
export function rememberedSimple(fallback: boolean): boolean {
  let v: string | null = null;
  try {
    v = window.localStorage?.getItem(SIMPLE_KEY) ?? null;
  } catch {
    v = null; // storage refused (a sandboxed file://): the default
  }
  return v === '1' ? true : v === '0' ? false : fallback;
}

function rememberSimple(on: boolean): void {
  try {
    window.localStorage?.setItem(SIMPLE_KEY, on ? '1' : '0');
  } catch {
    // storage refused: the choice lasts as long as the page (and its link)
  }
}

export function wireToolbar(lab: LabCore): ToolbarParts {
  const { store, scene, view, session, explain } = lab;
  let lastVideo: { size: number; head: string } | null = null;
  const recorder = new Recorder(scene.renderer.domElement, (video) => {
    void video.slice(0, 4).arrayBuffer().then((b) => {
      lastVideo = { size: video.size, head: [...new Uint8Array(b)].map((x) => x.toString(16).padStart(2, '0')).join('') };
    });
    downloadBlob(`pendulab-${store.status?.scenario ?? 'lab'}.webm`, video);
    explain(t('msg.recorded', { mb: (video.size / 1e6).toFixed(1) }), true);
  });
  const help = new HelpOverlay(byId('help'));
  const toolbar: Toolbar = new Toolbar(byId('toolbar'), byId('panel'), {
    run: session.run,
    reset: session.reset,
    step: session.step,
    record: () => {
      if (recorder.recording) recorder.stop();
      else {
        const why = recorder.start();
        explain(why !== null ? t('msg.noRecording', { why }) : t('msg.recording'), why === null);
      }
      toolbar.showRecording(recorder.recording);
    },
    help: () => help.toggle(),
    language: (l) => switchLanguage(lab, l),
    collapsed: () => undefined,
    present: (on) => {
      view.present = on;
      document.body.classList.toggle('present', on);
      toolbar.showPresenting(on);
    },
    simple: (on) => {
      view.simple = on;
      rememberSimple(on);
      document.body.classList.toggle('simple', on);
      toolbar.showSimple(on);
    },
  });
  document.body.classList.toggle('present', view.present);
  toolbar.showPresenting(view.present);
  document.body.classList.toggle('simple', view.simple);
  toolbar.showSimple(view.simple);
  return { toolbar, help, lastVideo: () => lastVideo };
}
