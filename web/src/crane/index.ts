// The lab's crane mode (docs/web.md, "Crane mode"; docs/cranes.md, "The lab's crane mode"): the panel
// (panel.ts), the crane drawn in the scene (drawing.ts) and the keys J L (trolley along x) and I K (across,
// y), held to drive. The core's live session runs the crane (crates/pendulab-core/src/live/crane.rs) in
// both transports; this module sends the `crane` command and `set_params`, and draws what comes back.
import type { LabCore } from '../wiring/session';
import { ownsKeys } from '../keyboard';
import { CraneDrawing } from './drawing';
import { CranePanel, RESIDUAL_WINDOW } from './panel';

const KEYS: Record<string, [number, number]> = { j: [-1, 0], l: [1, 0], i: [0, 1], k: [0, -1] };

export class CraneMode {
  readonly panel: CranePanel;
  private readonly drawing = new CraneDrawing();
  private held: string | null = null;

  constructor(
    private readonly lab: LabCore,
    parent: HTMLElement,
  ) {
    const { scene, session, store } = lab;
    this.panel = new CranePanel(parent, session.send, () => store.status?.crane?.v_max ?? 0.5, () => store.status?.params.g ?? 9.81);
    scene.addDrawing(this.drawing.group);
    scene.crane = {
      afterUpdate: (f) => this.drawing.update(this.active() ? f : null, store.status?.crane?.wind ?? null),
      hidesBody: () => this.active(),
    };
    document.addEventListener('keydown', (e) => this.key(e, true));
    document.addEventListener('keyup', (e) => this.key(e, false));
    let shown: unknown = null;
    setInterval(() => {
      const s = store.status;
      if (s !== shown) {
        shown = s;
        this.panel.sync(s?.crane);
      }
      this.panel.show(store.trailWindow(RESIDUAL_WINDOW), store.latest());
    }, 100);
  }

  /** True in the crane mode (the status has a crane). */
  active(): boolean {
    return (this.lab.store.status?.crane ?? null) !== null;
  }

  private key(e: KeyboardEvent, down: boolean): void {
    const k = e.key.toLowerCase();
    const dir = KEYS[k];
    if (dir === undefined || !this.active() || e.ctrlKey || e.metaKey || e.altKey || ownsKeys(e.target, e.key)) return;
    e.preventDefault();
    if (down && !e.repeat && this.held !== k) {
      this.held = k;
      this.panel.drive(dir);
    } else if (!down && this.held === k) {
      this.held = null;
      this.panel.drive([0, 0]);
    }
  }
}
