// The whole lab in the URL (docs/web.md, "Share and export"): reading a shared link at start (the view
// options, the commands that rebuild its scenario, its second pendulum, its paused time) and writing the
// current lab back into the address bar. Times in the link are simulated seconds [s], angles radians.
import type { Command } from '../protocol';
import { DEFAULT_VIEW, STEREO_MODES } from '../scene/options';
import type { ViewOptions } from '../scene/options';
import type { LabStore } from '../state';
import type { TwinOptions } from '../twin';
import type { ChosenPlot } from '../panels/chosen';
import type { TwinPanel } from '../panels/twin';
import { commandsFor, decodeUrl, encodeUrl, encodeView, fromStatus } from '../url';
import type { UrlScenario } from '../url';
import { language, t } from '../i18n';
import type { Explain } from './page';

/** Copies a link's view options into `view`: only known ones, of the default's type (the stereo mode
 *  one of its words); the others are returned as problems. */
export function applyLinkView(view: ViewOptions, given: Readonly<Record<string, unknown>>): string[] {
  const problems: string[] = [];
  for (const [k, v] of Object.entries(given)) {
    const d = (DEFAULT_VIEW as unknown as Record<string, unknown>)[k];
    const ok = d !== undefined && typeof d === typeof v && (k !== 'stereo' || (STEREO_MODES as readonly unknown[]).includes(v));
    if (ok) (view as unknown as Record<string, unknown>)[k] = v;
    else problems.push(`view: ${k} = ${String(v)} is not a view option`);
  }
  return problems;
}

/** The link the page was opened with, and the commands still to send for it. */
export class SharedLink {
  readonly value: UrlScenario;
  /** Commands sent once the first status arrives (the link's scenario; after a server restart, the shown one). */
  startup: Command[];
  /** With a second pendulum, the paused time's steps wait until both run (they go to both). */
  replay: Command[] = [];
  /** The link's second pendulum, made once the server has the link's scenario (null: none or done). */
  twinToRestore: TwinOptions | null;
  private chosen: ChosenPlot | null = null;
  private twin: TwinPanel | null = null;

  constructor(
    private readonly store: LabStore,
    private readonly view: ViewOptions,
    explain: Explain,
  ) {
    const fromUrl = decodeUrl(window.location.search);
    this.value = fromUrl.value;
    fromUrl.problems.push(...applyLinkView(view, fromUrl.value.view ?? {}));
    if (fromUrl.problems.length > 0) explain(t('msg.linkProblems', { what: fromUrl.problems.join('; ') }));
    this.startup = commandsFor(fromUrl.value);
    if (fromUrl.value.twin !== undefined) {
      this.replay = this.startup.filter((c) => c.type === 'step');
      this.startup = this.startup.filter((c) => c.type !== 'step');
    }
    this.twinToRestore = fromUrl.value.twin ?? null;
  }

  /** The panels whose state the link also carries (the chosen plot, the second pendulum). */
  attach(chosen: ChosenPlot, twin: TwinPanel): void {
    this.chosen = chosen;
    this.twin = twin;
    if (this.value.plot) chosen.choose(...this.value.plot);
  }

  /** The commands waiting for the first status (emptied). */
  takeStartup(): Command[] {
    const cmds = this.startup;
    this.startup = [];
    return cmds;
  }

  /** After a server restart (a new session starts from the default scenario): bring back the one shown. */
  restoreShown(): void {
    if (this.store.status !== null) this.startup = commandsFor(fromStatus(this.store.status));
  }

  /** The lab as a link: the server's status, the view options that differ from the defaults (and the simple
   *  view or not, always), the chosen
   *  plot, the second pendulum, the language. */
  lab(): UrlScenario {
    const s = this.store.status;
    const u: UrlScenario = s === null ? {} : fromStatus(s);
    u.view = encodeView(this.view as unknown as Record<string, boolean | number | string>, DEFAULT_VIEW as unknown as Record<string, boolean | number | string>);
    // the simple or the advanced view always said, so that a prepared lab opens as it was prepared (a link
    // that does not say it opens as the device last chose: wiring/toolbar.ts rememberedSimple)
    u.view.simple = this.view.simple;
    const choice = this.chosen?.choice;
    if (choice !== undefined && (choice.x !== 't' || choice.y !== 'theta')) u.plot = [choice.x, choice.y];
    if (this.twin?.on && this.twin.options.mode !== 'off') u.twin = { ...this.twin.options };
    u.lang = language();
    return u;
  }

  /** Writes the lab into the address bar (not before the link's own commands are sent). */
  write(): void {
    if (this.startup.length > 0 || this.store.status === null) return;
    const q = `?${encodeUrl(this.lab())}`;
    if (q !== window.location.search) window.history.replaceState(null, '', q);
  }
}
