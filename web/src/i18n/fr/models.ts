// The registry's parameters (label, help) and models (label) in French (Français), shown instead of the
// registry's English words (../index.ts: paramWords, modelWords). The units stay SI.
/** The registry's parameters in French: [label, help] by key (the units stay SI). */
export const FR_PARAMS: Record<string, [string, string]> = {
  length: ['longueur l', 'longueur de la tige du point de suspension à la masse'],
  mass: ['masse m', 'masse de la boule'],
  g: ['pesanteur g', 'intensité de la pesanteur (tout signe ; 0 permis)'],
  damping: ['frottement (amortissement linéaire) c', 'force de frottement −m c v, proportionnelle à la vitesse'],
  drag: ['résistance de l’air c_q', 'force −m c_q |v| v, quadratique en vitesse'],
  friction: ['frottement sec au point de suspension ε_f', 'frottement sec (Coulomb) au point de suspension : un couple m l² ε_f contre l’oscillation, quelle que soit sa vitesse'],
  friction_speed: ['vitesse de lissage du frottement sec ω_ε', 'sous cette vitesse angulaire le frottement sec s’efface en douceur, comme tanh(|ω|/ω_ε)'],
  forcing_amplitude: ['forçage : intensité A', 'force périodique par masse A cos(ω t + ψ) dans la direction e'],
  forcing_omega: ['forçage : pulsation ω', 'à quelle vitesse le forçage oscille'],
  forcing_phase: ['forçage : phase ψ', 'phase du forçage à t = 0'],
  forcing_x: ['direction du forçage e : x', 'composante x de la direction du forçage (normalisée)'],
  forcing_y: ['direction du forçage e : y', 'composante y de la direction du forçage'],
  forcing_z: ['direction du forçage e : z', 'composante z de la direction du forçage'],
  gravity_x: ['direction de la pesanteur d : x', 'composante x de la direction de la pesanteur (normalisée)'],
  gravity_y: ['direction de la pesanteur d : y', 'composante y de la direction de la pesanteur'],
  gravity_z: ['direction de la pesanteur d : z', 'composante z de la direction de la pesanteur'],
  frame_rate: ['vitesse de rotation du référentiel |Ω|', 'à quelle vitesse tourne le référentiel (Terre : 7,292e-5)'],
  latitude: ['latitude λ', 'latitude du lieu (pendule de Foucault)'],
  radius: ['rayon de la flèche R', 'distance du point de suspension à l’axe de rotation de la grue'],
  rate: ['vitesse de rotation de la grue ω', 'à quelle vitesse tourne la flèche'],
  height: ['hauteur du point de suspension h', 'hauteur de la flèche'],
  amplitude: ['amplitude de vibration A', 'amplitude de l’oscillation verticale du point de suspension'],
  frequency: ['fréquence de vibration ν', 'pulsation de l’oscillation du point de suspension'],
  stiffness: ['raideur du ressort k', 'raideur du ressort ; la longueur l est la longueur au repos'],
  restitution: ['coefficient de restitution e', 'élasticité du fil quand il se tend d’un coup (0 … 1)'],
};

/** The registry's models in French (their labels). */
export const FR_MODELS: Record<string, string> = {
  ideal: 'Pendule idéal',
  damped: 'Amorti et forcé',
  rotating: 'Sur la Terre qui tourne (Foucault)',
  slewing: 'Grue pivotante',
  vibrating: 'Point de suspension vibrant (Kapitza)',
  sampled_pivot: 'Point de suspension sur un chemin donné',
  spring: 'Ressort oscillant',
  string: 'Pendule à fil',
  crane: 'Pont roulant (mode grue)',
};
