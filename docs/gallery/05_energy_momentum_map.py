"""The energy–momentum map and its monodromy.

Every motion has an energy E and a vertical angular momentum J₃; the colour is the rotation number
|W| = |Δφ|/2π per period of z (T-4.5). The image is bounded by the conical orbits; carried once
around the unstable top (0, m g l), W comes back changed by exactly ±1 (T-6.4).

Lab: s=rosette&plot=energy,j3
"""

import pendulab as pl
from pendulab.plot import plot_em_map

p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
emmap = pl.em_map(p, grid=(160, 160))
plot_em_map(emmap, "energy_momentum_map.png")
