"""Holm's Figure 2: the motion in the space of the rotation invariants.

In (σ₁, σ₂, σ₃) = (z/l, ż/l, |v|²/l²) the orbit is the intersection of the surface C = 0 fixed by
J₃ (T-3.3) with the plane of constant energy H = ½σ₃ + gσ₁; the reduced flow is σ̇ = ∇H × ∇C
(T-3.4).

Lab: s=rosette&method=rattle4&dt=0.001&plot=z,zdot
"""

import numpy as np
import pendulab as pl
from pendulab.plot import plot_reduced

p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
s0 = p.state_from_angles(theta=np.radians(60), phi=0.0, theta_dot=0.0, phi_dot=2.0)
tr = pl.simulate(p, s0, t_end=5.0, method="rattle4", dt=1e-3, save_every=5)

plot_reduced(tr, "reduced_space.png")
