// End-to-end checks of the classroom lab (issue 15), run by smoke.mjs on its page after its own checks:
// the layout (controls never over the canvas, the whole sphere of reach in view) at a projector's and a
// phone's size, every shipped scenario loaded without console errors, the period timer against the exact
// period, the keyboard shortcuts and a focused slider, the energy bars adding up, two pendulums, the
// recording, the anaglyph's frame rate and the second language. Waits are generous (a loaded 2-core
// machine), but every check compares against a bound and can fail.
// One module per topic (classroom/): layout.mjs (layout, touch), scenarios.mjs (scenarios, plots, share
// link), period.mjs (period timer), keyboard.mjs (keyboard, inclusion tools), twin.mjs (energy, two
// pendulums), recording.mjs (recording, anaglyph), language.mjs (language, axe); this file re-exports the
// checks smoke.mjs runs.
export { checkLayout, checkTouch } from './classroom/layout.mjs';
export { checkScenarios, checkPlots, checkShare } from './classroom/scenarios.mjs';
export { checkPeriodTimer } from './classroom/period.mjs';
export { checkKeyboard } from './classroom/keyboard.mjs';
export { checkEnergyAndTwin } from './classroom/twin.mjs';
export { checkRecordingAndStereo } from './classroom/recording.mjs';
export { dataRows, checkLanguage, checkAxe } from './classroom/language.mjs';
