// The lab's session with the server (or the in-page engine): the one `send` every control uses (mirrored
// to the second pendulum), run / reset / step, and the core every wiring module shares. Commands carry SI
// values (m, s, kg, rad); the server checks them.
import type { Connection } from '../connection';
import type { Command } from '../protocol';
import type { LabStore } from '../state';
import type { PendulumScene } from '../scene/scene';
import type { ViewOptions } from '../scene/options';
import type { TwinPanel } from '../panels/twin';
import { t } from '../i18n';
import type { Explain } from './page';

export class Session {
  /** The connection, once made (commands before it are refused with a message). */
  conn: Connection | null = null;
  /** The second-pendulum panel, which mirrors every command sent to the first. */
  twin: TwinPanel | null = null;

  constructor(
    private readonly store: LabStore,
    private readonly explain: Explain,
  ) {}

  readonly send = (cmd: Command): void => {
    if (this.conn === null || !this.conn.send(cmd)) this.explain(t('msg.notConnected'));
    else this.twin?.mirror(cmd);
  };

  /** Start / pause. */
  readonly run = (): void => this.send({ type: this.store.status?.paused === false ? 'pause' : 'resume' });
  readonly reset = (): void => this.send({ type: 'reset' });
  readonly step = (): void => this.send({ type: 'step', n: 1 });

  /** Commands sent on the current connection (0 before it opens). */
  sent(): number {
    return this.conn?.sent ?? 0;
  }
}

/** What every wiring module works with: the store, the 3-D scene, the view options, the session and the message line. */
export interface LabCore {
  readonly store: LabStore;
  readonly scene: PendulumScene;
  readonly view: ViewOptions;
  readonly session: Session;
  readonly explain: Explain;
}
