// The keyboard (docs/web.md, "Keyboard"): the focusable 3-D view (arrows turn the camera, + − zoom,
// Shift + ← → move the bob's start by degrees) and the page's shortcuts (space, r, s, h, d, Escape).
// Angles sent to the server in radians.
import { ownsKeys, shortcutFor, viewKey } from '../keyboard';
import { describeMotion } from '../describe';
import { DEG, energySplit, sphericalAngles } from '../measure';
import type { HelpOverlay } from '../panels/help';
import type { Tools } from '../panels/tools';
import { t } from '../i18n';
import type { LabCore } from './session';

/** The 3-D view by keyboard: focusable, the arrows turn the camera, + − zoom, Shift + ← → the bob's start. */
function wireCanvasKeys(lab: LabCore): void {
  const { scene, store, session, explain } = lab;
  const canvas = scene.renderer.domElement;
  canvas.tabIndex = 0;
  canvas.setAttribute('aria-label', `${t('page.scene')}. ${t('help.camera')}; ${t('key.shift')} + ← →: ${t('help.bobKeys')}`);
  canvas.addEventListener('keydown', (e) => {
    const k = viewKey(e.key, e.shiftKey);
    if (k === null || e.ctrlKey || e.metaKey || e.altKey) return;
    e.preventDefault();
    if ('orbit' in k) {
      scene.orbitBy(k.orbit[0], k.orbit[1], k.zoom);
      return;
    }
    const s = store.status;
    if (s === null) return;
    if (!s.paused) session.send({ type: 'pause' });
    const a = sphericalAngles(s.start.x);
    const theta = Math.min(Math.max(a.theta + k.bob / DEG, 0), Math.PI);
    session.send({ type: 'set_state', theta, phi: a.phi, theta_dot: 0, phi_dot: 0 });
    explain(t('describe.text', { theta: (theta * DEG).toFixed(0), dir: t('describe.rest'), v: '0.00' }), true);
  });
}

/** Speaks the motion now (the `d` key): angle, direction, speed, energy split. */
function describeNow(lab: LabCore, tools: Tools): void {
  const { store } = lab;
  const latest = store.latest();
  const p = store.status?.params;
  const split = latest ? energySplit(latest, p?.mass ?? 1, p?.g ?? 9.81, p?.length ?? 1, store.work) : null;
  tools.describe(describeMotion(store.displayed(), split), performance.now(), true);
}

export function wireKeys(lab: LabCore, help: HelpOverlay, tools: Tools): void {
  wireCanvasKeys(lab);
  const { session } = lab;
  document.addEventListener('keydown', (e) => {
    const plain = !e.ctrlKey && !e.metaKey && !e.altKey;
    if ((e.key === 'd' || e.key === 'D') && plain && !ownsKeys(e.target, e.key) && !help.open) {
      describeNow(lab, tools);
      return;
    }
    const action = shortcutFor(e.key, !plain);
    if (action === null) return;
    if (action === 'close') {
      if (help.open) help.toggle(false);
      return;
    }
    if (ownsKeys(e.target, e.key)) return;
    if (help.open && action !== 'help') return;
    e.preventDefault();
    if (action === 'run') session.run();
    else if (action === 'reset') session.reset();
    else if (action === 'step') session.step();
    else help.toggle();
  });
}
