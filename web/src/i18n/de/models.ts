// The registry's parameters (label, help) and models (label) in German (Deutsch), shown instead of the
// registry's English words (../index.ts: paramWords, modelWords). The units stay SI.
/** The registry's parameters in German: [label, help] by key (the units stay SI). */
export const DE_PARAMS: Record<string, [string, string]> = {
  length: ['Länge l', 'Länge der Stange vom Aufhängepunkt zur Kugel'],
  mass: ['Masse m', 'Masse der Kugel'],
  g: ['Schwerebeschleunigung g', 'Stärke der Schwerkraft (jedes Vorzeichen; 0 erlaubt)'],
  damping: ['Reibung (lineare Dämpfung) c', 'Reibungskraft −m c v, proportional zur Geschwindigkeit'],
  drag: ['Luftwiderstand c_q', 'Kraft −m c_q |v| v, quadratisch in der Geschwindigkeit'],
  friction: ['trockene Reibung am Aufhängepunkt ε_f', 'Haftreibung (Coulomb) am Aufhängepunkt: ein Drehmoment m l² ε_f gegen die Schwingung, gleich wie schnell sie ist'],
  friction_speed: ['Glättungsgeschwindigkeit der trockenen Reibung ω_ε', 'unter dieser Winkelgeschwindigkeit klingt die trockene Reibung sanft ab, wie tanh(|ω|/ω_ε)'],
  forcing_amplitude: ['Antrieb: Stärke A', 'periodische Kraft pro Masse A cos(ω t + ψ) in Richtung e'],
  forcing_omega: ['Antrieb: Kreisfrequenz ω', 'wie schnell der Antrieb schwingt'],
  forcing_phase: ['Antrieb: Phase ψ', 'Phase des Antriebs bei t = 0'],
  forcing_x: ['Antriebsrichtung e: x', 'x-Komponente der Antriebsrichtung (wird normiert)'],
  forcing_y: ['Antriebsrichtung e: y', 'y-Komponente der Antriebsrichtung'],
  forcing_z: ['Antriebsrichtung e: z', 'z-Komponente der Antriebsrichtung'],
  gravity_x: ['Schwerkraftrichtung d: x', 'x-Komponente der Richtung der Schwerkraft (wird normiert)'],
  gravity_y: ['Schwerkraftrichtung d: y', 'y-Komponente der Richtung der Schwerkraft'],
  gravity_z: ['Schwerkraftrichtung d: z', 'z-Komponente der Richtung der Schwerkraft'],
  frame_rate: ['Drehrate des Bezugssystems |Ω|', 'wie schnell sich das Bezugssystem dreht (Erde: 7,292e-5)'],
  latitude: ['geografische Breite λ', 'Breite des Ortes (Foucault-Pendel)'],
  radius: ['Auslegerradius R', 'Abstand des Aufhängepunkts von der Drehachse des Krans'],
  rate: ['Drehrate des Krans ω', 'wie schnell sich der Ausleger dreht'],
  height: ['Höhe des Aufhängepunkts h', 'Höhe des Auslegers'],
  amplitude: ['Rüttelamplitude A', 'Amplitude der senkrechten Schwingung des Aufhängepunkts'],
  frequency: ['Rüttelfrequenz ν', 'Kreisfrequenz der Schwingung des Aufhängepunkts'],
  stiffness: ['Federkonstante k', 'Steifigkeit der Feder; die Länge l ist die entspannte Länge'],
  restitution: ['Stoßzahl e', 'wie elastisch die Schnur beim Straffen zurückfedert (0 … 1)'],
};

/** The registry's models in German (their labels). */
export const DE_MODELS: Record<string, string> = {
  ideal: 'Ideales Pendel',
  damped: 'Gedämpft und angetrieben',
  rotating: 'Auf der drehenden Erde (Foucault)',
  slewing: 'Drehkran',
  vibrating: 'Gerüttelter Aufhängepunkt (Kapitza)',
  sampled_pivot: 'Aufhängepunkt auf vorgegebener Bahn',
  spring: 'Schwingfeder',
  string: 'Pendel an einer Schnur',
  crane: 'Portalkran (Kranmodus)',
};
