"""A movie of the rosette, every frame from the exact solution.

Baroudy animated the spherical pendulum in Maple from Jacobi's elliptic functions with 60 precomputed
positions; here every frame is the exact state at its time (T-4.2–T-4.4), so any frame rate costs the
same. The 3-D panel and the top view, 6 s of motion.

Lab: s=rosette
"""

import numpy as np
import pendulab as pl

p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
s0 = p.state_from_angles(theta=np.radians(60), phi=0.0, theta_dot=0.0, phi_dot=2.0)
sol = pl.exact(p, s0)
sol.animate("rosette.mp4", t=(0, 6), fps=20, size=(640, 320), panels=["3d", "top"])
