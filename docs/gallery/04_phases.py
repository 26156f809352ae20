"""Dynamic and geometric phase of three orbits.

The azimuthal advance per period of z splits into a dynamic part, 2 T_z ⟨K⟩ / J₃, and a geometric
part, minus the area the reduced orbit encloses in the (z, p_z) plane over J₃ (T-5.1). Both come from
the exact solution: no integration.

Lab: s=rosette&plot=t,phi
"""

import numpy as np
import pendulab as pl
from pendulab.plot import plot_phases

p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
orbits = {
    f"θ₀ = {deg}°": pl.exact(
        p, p.state_from_angles(theta=np.radians(deg), phi=0.0, theta_dot=0.0, phi_dot=2.0)
    )
    for deg in (30, 60, 90)
}
plot_phases(orbits, "phases.png")
