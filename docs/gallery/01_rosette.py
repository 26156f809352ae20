"""The rosette: a generic orbit on the sphere and seen from above.

Released 60° from the downward vertical with a sideways spin, the bob swings between two heights
z₁ and z₂ (the circles, from the exact solution, T-4.1) while its lowest point advances by
Δφ per period of z (T-4.5). Integrated with the default method, RATTLE, for 20 s.

Lab: s=rosette&plot=x,y
"""

import numpy as np
import pendulab as pl
from pendulab.plot import plot_trajectory

p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)  # m, m/s², kg
s0 = p.state_from_angles(theta=np.radians(60), phi=0.0, theta_dot=0.0, phi_dot=2.0)  # rad, rad/s
tr = pl.simulate(p, s0, t_end=20.0, method="rattle", dt=1e-3, save_every=10)
sol = pl.exact(p, s0)

plot_trajectory(tr, "rosette.png", exact=sol, kind="both")
print(f"z-period {sol.period_z:.6f} s, advance per z-period {sol.azimuth_advance:.6f} rad")
