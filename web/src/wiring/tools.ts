// The classroom tools (panels/tools.ts: presets, stopwatch, period timer, ruler, protractor, sound,
// description) and the fitted-data panel wired to the session and the view. Ruler and protractor
// offsets are in metres in the scene, rounded to mm for the link.
import { Tools } from '../panels/tools';
import { FitDataPanel } from '../panels/fitdata';
import { loadCommands } from '../fitdata';
import { t } from '../i18n';
import { byId } from './page';
import type { LabCore } from './session';

export function wireTools(lab: LabCore): Tools {
  const { store, scene, view, session, explain } = lab;
  const tools: Tools = new Tools(byId('tools'), store, {
    send: session.send,
    explain,
    overlay: (which, on) => {
      view[which] = on;
    },
    move: (which, by) => {
      const [shift, lift] = which === 'ruler' ? (['rulerShift', 'rulerLift'] as const) : (['protractorShift', 'protractorLift'] as const);
      const round = (v: number) => Math.round(v * 1000) / 1000; // link-friendly numbers
      view[shift] = by === null ? 0 : round(view[shift] + by[0]);
      view[lift] = by === null ? 0 : round(view[lift] + by[1]);
      view[which] = true;
      tools.showOverlay(which, true);
    },
  });
  // a measured data file fitted by the server: its scenario loaded like a shared link, its path drawn
  new FitDataPanel(byId('tools'), {
    loaded: (answer, name) => {
      scene.setMeasured(answer.measured?.x ?? null);
      if (answer.lab !== null) for (const c of loadCommands(answer.lab)) session.send(c);
      explain(t('fit.loaded', { name }), true);
    },
    cleared: () => scene.setMeasured(null),
    explain,
  });
  tools.showOverlay('ruler', view.ruler);
  tools.showOverlay('protractor', view.protractor);
  return tools;
}
