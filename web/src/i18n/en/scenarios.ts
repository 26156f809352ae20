// The page's English words, scenarios: the shipped scenarios' titles, the models' one-line help, the names of
// keys in the help overlay, the simple view's button and pendulums 3 and 4. Part of the reference table `EN`
// (index.ts); every other language has the same keys (`ScenariosWords`). {name} marks a value filled in by
// t(). docs/web.md, "Languages".
export const EN_SCENARIOS = {
  'scenario.conical': 'Conical pendulum at 45°',
  'scenario.damped': 'Damped rosette (c = 0.05 1/s)',
  'scenario.foucault': 'Foucault pendulum at 49° N, Earth’s rotation exaggerated (Ω = 0.02 rad/s)',
  'scenario.inverted_g': 'Inverted gravity: the rosette mirrored',
  'scenario.near_top': 'Released just below the top',
  'scenario.over_the_top': 'Over the top: planar revolutions',
  'scenario.planar_large': 'Planar swing of amplitude 150°',
  'scenario.rosette': 'Rosette: 60° release with sideways spin',
  'scenario.crane_hoist': 'Gantry crane: ZV-shaped 8 m move while hoisting 12 m -> 6 m, in a cross wind',
  'scenario.slewing_crane': 'Slewing crane: R = 5 m, ω = 0.3 rad/s, l = 10 m',
  'scenario.small_ellipse': 'Small ellipse with Airy precession',
  'scenario.string_slack': 'String pendulum: slack at z = l/2, inelastic snap',
  'scenario.swinging_spring': 'Swinging spring at the 1:1:2 resonance',
  'scenario.zero_g': 'Zero gravity: a great circle',
  'modelHelp.ideal': 'a rod without friction: the textbook pendulum',
  'modelHelp.damped': 'with friction, air drag or a periodic push',
  'modelHelp.rotating': 'seen from the turning Earth: the swing plane turns (Foucault)',
  'modelHelp.slewing': 'hanging from the boom of a turning crane',
  'modelHelp.vibrating': 'the pivot shaken up and down: it can stand upside down (Kapitza)',
  'modelHelp.sampled_pivot': 'the pivot moves along a given path',
  'modelHelp.spring': 'a spring instead of a rod: it swings and bounces',
  'modelHelp.string': 'a string instead of a rod: it can go slack and snap taut',
  'key.space': 'Space',
  'key.page': 'Page ↑ / Page ↓',
  'key.shift': 'Shift',
  'toolbar.simpleShort': 'Simple',
  'toolbar.simple': 'simple view: only the classroom tools (length, mass, gravity, friction, stopwatch, period, ruler, energy); press again for everything',
  'extras.add': '+ another pendulum (own length, mass, start)',
  'extras.pendulum': 'pendulum {n}',
  'extras.remove': 'remove pendulum {n}',
  'extras.title': 'Up to four pendulums',
  'extras.hint': 'With the second pendulum on “its own length, mass and start”: add pendulums 3 and 4, then “start both” starts all, each timed by its own period timer.',
};

/** The keys of this part, each a string: every language's scenarios table has exactly these. */
export type ScenariosWords = { readonly [K in keyof typeof EN_SCENARIOS]: string };
