ring
inner_radius=4.72 mm
outer_radius=10 mm
thickness=1 mm
E_r=10 GPa
E_phi=40 GPa
G=4 GPa
nu_phi_r=0.28
gap=0.02 mm
