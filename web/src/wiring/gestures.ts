// Pointer gestures on the 3-D view: dragging the bob pauses, then the start follows the pointer (at rest
// there); pulling the velocity arrow pauses, then the start velocity [m/s] follows it (x kept). One
// throttle for both, so a late send of one gesture never lands after the next; the server checks (and
// projects onto the constraint) every state.
import { throttle } from '../panels/params';
import type { Vec3 } from '../protocol';
import { t } from '../i18n';
import type { LabCore } from './session';

export function wireGestures(lab: LabCore): void {
  const { store, scene, session, explain } = lab;
  const sendStart = throttle((x: Vec3, v: Vec3) => {
    session.send({ type: 'set_state', x, v, project: true });
  }, 50);
  const pauseForGesture = () => {
    if (store.status?.paused === false) session.send({ type: 'pause' });
  };
  scene.enableDrag(
    (x, phase) => {
      if (phase === 'start') pauseForGesture();
      sendStart(x, [0, 0, 0]);
      if (phase === 'end') explain(t('msg.dragged'), true);
    },
    (x, pulled, phase) => {
      if (phase === 'start') {
        pauseForGesture();
        explain(t('msg.pull'), true);
        return;
      }
      if (pulled === null) return;
      sendStart(x, pulled.v);
      const cap = pulled.capped ? t('msg.capped') : '';
      const words = { v: pulled.speed.toFixed(2), cap };
      explain(phase === 'end' ? t('msg.velocitySet', words) : t('msg.velocity', words), true);
    },
  );
}
