#!/usr/bin/python3
"""External finite-element reference for the orthotropic ring of seed 002 (CalculiX ccx).

Writes a CalculiX input deck for a quarter ring 0 <= phi <= pi/2 of plane-stress CPS8 elements
(cylindrical material orientation, engineering constants), runs ccx, and extracts
  * the load P the link carries: twice the x-force the rigid half-disc puts on the quarter
    (sum over the inner nodes of the radial reaction times cos(phi)), and the same force from the
    reactions of the phi = pi/2 symmetry plane (their agreement is the FE's equilibrium);
  * sigma_r and sigma_phi (ccx nodal stresses, global axes) along the radial lines phi = 0 and
    phi = pi/2 at the 21 equally spaced radii r1 + k(r2 - r1)/20.

Boundary conditions, as Catena solves the problem (include/catena/composite/ring.hpp, bilateral
contact, seed 002 eq. (2)): inner nodes U_r = delta*cos(phi) in a local cylindrical *TRANSFORM,
tangential displacement free (tau = 0); symmetry U_phi = 0 on phi = 0 and phi = pi/2; outer edge
free. Units: mm, N, MPa. Python 3 standard library only. ccx reads at most 20 characters per
field: every real is written with %.13e (a 21-character %.15e silently loses its exponent's last
digit: y = 1.111438e-01 mm was read as 1.111 mm, and ccx reported nonpositive Jacobians).

Usage: generate.py [--levels 0 1 2] [--keep DIR] [--out DIR]
(writes loads.csv and profiles.csv next to this file unless --out)
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))

# The ring of tests/validation/composite_paper_test.cpp (mm, MPa): r2 = 10 mm, t = 1 mm,
# gap 2*delta = 0.02 mm, E_phi = 40 GPa, nu_phi_r = 0.28.
R2 = 10.0
THICKNESS = 1.0      # the link's thickness; the loads are reported for it
# The CPS8 layer's thickness. ccx expands each plane-stress element into one C3D20 layer with free
# faces: a 3-D plate, which is plane stress only where the layer is thin against the in-plane
# stress gradients. At the link's own 1 mm the thin ring's outer-fibre sigma_phi at phi = pi/2 is
# -2.50 MPa instead of -1.03 and the load 4.9e-4 too high; 0.01 mm is still 0.02 MPa off there;
# 0.001 and 0.0001 mm agree to 4e-4 MPa (README). Loads are scaled by THICKNESS/FE_THICKNESS.
FE_THICKNESS = 0.001
DELTA = 0.01
E_PHI = 40000.0
NU_PHI_R = 0.28
MATERIALS = {
    # name: (E_r, E_phi, G)
    "ortho": (10000.0, E_PHI, 4000.0),                         # E_r/E_phi = 0.25, G = 4 GPa
    "iso": (E_PHI, E_PHI, E_PHI / (2.0 * (1.0 + NU_PHI_R))),   # isotropic, G = E/(2(1 + nu))
    "iso_gkept": (E_PHI, E_PHI, 4000.0),                       # E_r = E_phi, G = 0.1 E_phi kept
}
ALPHAS = (0.472, 0.95)
BLOCKS = 20  # the profiles are read at the 21 radii r1 + k(r2 - r1)/20 (mesh lines)


def radial_edges(alpha, level):
    """Element edges in r: 20 equal blocks; block 0 (the corner zone) graded 1:2:4 toward r1,
    block 1 halved; every element split in 2**level."""
    r1 = alpha * R2
    h = (R2 - r1) / BLOCKS
    base = [r1, r1 + h / 7.0, r1 + 3.0 * h / 7.0, r1 + h, r1 + 1.5 * h]
    base += [r1 + k * h for k in range(2, BLOCKS + 1)]
    return refine(base, level), r1, h


def angular_edges(alpha, level, smallest_radial):
    """Element edges in phi from 0 to pi/2, geometrically graded toward pi/2 (the end of contact,
    where the stress is singular at the inner fibre): the last element's arc at r1 equals the
    smallest radial element; 71 elements at level 0."""
    count = 71
    r1 = alpha * R2
    d_last = smallest_radial / r1
    # ratio q with d_last * (q**count - 1)/(q - 1) = pi/2 (bisection)
    lo, hi = 1.0 + 1e-9, 2.0
    for _ in range(200):
        q = 0.5 * (lo + hi)
        total = d_last * (q ** count - 1.0) / (q - 1.0)
        if total > math.pi / 2:
            hi = q
        else:
            lo = q
    q = 0.5 * (lo + hi)
    sizes = [d_last * q ** k for k in range(count)]  # from pi/2 backwards
    scale = (math.pi / 2) / sum(sizes)
    edges = [math.pi / 2]
    for s in sizes:
        edges.append(edges[-1] - s * scale)
    edges[-1] = 0.0
    return refine(sorted(edges), level)


def refine(edges, level):
    for _ in range(level):
        out = []
        for a, b in zip(edges[:-1], edges[1:]):
            out += [a, 0.5 * (a + b)]
        edges = out + [edges[-1]]
    return edges


def build_mesh(alpha, level):
    rs, r1, h = radial_edges(alpha, level)
    phis = angular_edges(alpha, level, rs[1] - rs[0])
    nr, nphi = len(rs) - 1, len(phis) - 1
    # node lattice: I = 0..2nr (radial, odd = midside), J = 0..2nphi; (odd, odd) does not exist
    R = []
    for i in range(nr):
        R += [rs[i], 0.5 * (rs[i] + rs[i + 1])]
    R.append(rs[-1])
    P = []
    for j in range(nphi):
        P += [phis[j], 0.5 * (phis[j] + phis[j + 1])]
    P.append(phis[-1])
    ncol = 2 * nphi + 1

    def nid(i, j):
        return i * ncol + j + 1

    nodes = {}
    for i in range(2 * nr + 1):
        for j in range(2 * nphi + 1):
            if i % 2 == 1 and j % 2 == 1:
                continue
            nodes[nid(i, j)] = (R[i], P[j])
    elements = []
    for i in range(nr):
        for j in range(nphi):
            a, b = 2 * i, 2 * j
            # counter-clockwise in (r, phi), which maps orientation-preserving to (x, y)
            elements.append((nid(a, b), nid(a + 2, b), nid(a + 2, b + 2), nid(a, b + 2),
                             nid(a + 1, b), nid(a + 2, b + 1), nid(a + 1, b + 2), nid(a, b + 1)))
    inner = [nid(0, j) for j in range(2 * nphi + 1)]
    phi0 = [nid(i, 0) for i in range(2 * nr + 1)]
    phi90 = [nid(i, 2 * nphi) for i in range(2 * nr + 1)]
    # the 21 profile radii are element edges: lattice rows of those radii
    profile_rows = []
    for k in range(BLOCKS + 1):
        target = r1 + k * h
        i = min(range(len(R)), key=lambda ii: abs(R[ii] - target))
        assert abs(R[i] - target) < 1e-9 * R2, (k, R[i], target)
        profile_rows.append(i)
    return dict(nodes=nodes, elements=elements, inner=inner, phi0=phi0, phi90=phi90,
                profile_rows=profile_rows, nid=nid, nphi=nphi, R=R)


def write_deck(path, mesh, material):
    e_r, e_phi, g = MATERIALS[material]
    nu_rphi = NU_PHI_R * e_r / e_phi  # Maxwell-Betti: nu_rphi/E_r = nu_phir/E_phi
    nodes = mesh["nodes"]
    with open(path, "w") as f:
        f.write("** seed 002 ring, quarter model, generated by generate.py\n*NODE, NSET=NALL\n")
        for n, (r, p) in nodes.items():
            f.write("%d,%.13e,%.13e\n" % (n, r * math.cos(p), r * math.sin(p)))
        f.write("*ELEMENT, TYPE=CPS8, ELSET=EALL\n")
        for k, e in enumerate(mesh["elements"], 1):
            f.write("%d,%s\n" % (k, ",".join(str(x) for x in e)))
        f.write("*NSET, NSET=INNER\n")
        for n in mesh["inner"]:
            f.write("%d\n" % n)
        f.write("*NSET, NSET=SYM90\n")
        for n in mesh["phi90"]:
            f.write("%d\n" % n)
        # material axes: 1 radial, 2 hoop, 3 axial (cylindrical system about z)
        f.write("*ORIENTATION, NAME=CYL, SYSTEM=CYLINDRICAL\n0.,0.,0.,0.,0.,1.\n")
        f.write("*MATERIAL, NAME=RING\n*ELASTIC, TYPE=ENGINEERING CONSTANTS\n")
        # E1 E2 E3 nu12 nu13 nu23 G12 G13 / G23: the out-of-plane constants (E3 = E_r,
        # nu13 = 0.3, nu23 = nu_phir, G13 = G23 = G) do not enter plane stress
        f.write("%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n%.10g,0.\n" %
                (e_r, e_phi, e_r, nu_rphi, 0.3, NU_PHI_R, g, g, g))
        f.write("*SOLID SECTION, ELSET=EALL, MATERIAL=RING, ORIENTATION=CYL\n%.10g\n" % FE_THICKNESS)
        # local cylindrical axes on the inner nodes (DOF 1 radial, DOF 2 tangential, about z):
        # U_r = delta*cos(phi) prescribed, the tangential displacement free (tau = 0)
        inner = mesh["inner"]
        f.write("*TRANSFORM, NSET=INNER, TYPE=C\n0.,0.,0.,0.,0.,1.\n")
        f.write("*STEP\n*STATIC\n*BOUNDARY\n")
        for n in inner:
            f.write("%d,1,1,%.13e\n" % (n, DELTA * math.cos(nodes[n][1])))  # 002 eq. (2)
        # symmetry U_phi = 0: local DOF 2 at the two inner corner nodes, u_y on phi = 0 and u_x
        # on phi = pi/2 elsewhere
        f.write("%d,2,2,0.\n%d,2,2,0.\n" % (inner[0], inner[-1]))
        for n in mesh["phi0"][1:]:
            f.write("%d,2,2,0.\n" % n)
        for n in mesh["phi90"][1:]:
            f.write("%d,1,1,0.\n" % n)
        f.write("*NODE PRINT, NSET=INNER, GLOBAL=YES\nRF\n")
        f.write("*NODE PRINT, NSET=SYM90, GLOBAL=YES\nRF\n")
        f.write("*EL FILE\nS\n*END STEP\n")


def read_reactions(dat_path):
    """{node: (fx, fy)} from the .dat file, per *NODE PRINT block (list of dicts)."""
    blocks, cur = [], None
    with open(dat_path) as f:
        for line in f:
            if "forces (fx,fy,fz)" in line:
                cur = {}
                blocks.append(cur)
                continue
            parts = line.split()
            if cur is not None and len(parts) == 4:
                try:
                    cur[int(parts[0])] = (float(parts[1]), float(parts[2]))
                except ValueError:
                    cur = None
    return blocks


def read_stresses(frd_path):
    """{node: (sxx, syy, szz, sxy)} from the STRESS block of the .frd file."""
    out, inside = {}, False
    with open(frd_path) as f:
        for line in f:
            if line.startswith(" -4"):
                inside = line.split()[1] == "STRESS"
                continue
            if inside and line.startswith(" -3"):
                inside = False
                continue
            if inside and line.startswith(" -1"):
                n = int(line[3:13])
                vals = [float(line[13 + 12 * k:25 + 12 * k]) for k in range(6)]
                out[n] = (vals[0], vals[1], vals[2], vals[3])
    return out


def run_case(alpha, material, level, workdir):
    mesh = build_mesh(alpha, level)
    job = "ring_%s_%s_L%d" % (str(alpha).replace(".", "p"), material, level)
    write_deck(os.path.join(workdir, job + ".inp"), mesh, material)
    t0 = time.perf_counter()
    proc = subprocess.run(["ccx", job], cwd=workdir, capture_output=True, text=True)
    seconds = time.perf_counter() - t0
    if proc.returncode != 0 or "Job finished" not in proc.stdout:
        sys.exit("ccx failed for %s:\n%s\n%s" % (job, proc.stdout[-2000:], proc.stderr[-2000:]))
    inner_rf, sym_rf = read_reactions(os.path.join(workdir, job + ".dat"))
    # x-force of the half-disc on the quarter: ccx's RF is the elements' nodal force, here the
    # constraint force; its radial part times cos(phi) (the tangential part is the symmetry
    # planes' at the two corner nodes, and ~0 elsewhere: tau = 0)
    nodes = mesh["nodes"]
    fx_contact = 0.0
    for n, (fx, fy) in inner_rf.items():
        p = nodes[n][1]
        fx_contact += (fx * math.cos(p) + fy * math.sin(p)) * math.cos(p)
    fx_section = -sum(fx for fx, fy in sym_rf.values())
    scale = THICKNESS / FE_THICKNESS
    s = read_stresses(os.path.join(workdir, job + ".frd"))
    nid, nphi = mesh["nid"], mesh["nphi"]
    prof = []
    for i in mesh["profile_rows"]:
        r = mesh["R"][i]
        s0 = s[nid(i, 0)]          # phi = 0: r = x, phi = y
        s90 = s[nid(i, 2 * nphi)]  # phi = pi/2: r = y, phi = -x
        prof.append((r, s0[0], s0[1], s90[1], s90[0]))
    return dict(job=job, nodes=len(mesh["nodes"]), elements=len(mesh["elements"]), seconds=seconds,
                load_contact=2.0 * fx_contact * scale, load_section=2.0 * fx_section * scale, profile=prof)


def ccx_version():
    proc = subprocess.run(["ccx", "-v"], capture_output=True, text=True)
    for line in (proc.stdout + proc.stderr).splitlines():
        if "Version" in line:
            return line.strip()
    return "unknown"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--levels", type=int, nargs="+", default=[0, 1, 2])
    ap.add_argument("--keep", help="directory to keep the ccx files in")
    ap.add_argument("--out", default=HERE)
    args = ap.parse_args()
    workdir = args.keep or tempfile.mkdtemp(prefix="ring_ccx_")
    os.makedirs(workdir, exist_ok=True)
    print(ccx_version())
    loads = ["alpha,material,E_r_MPa,E_phi_MPa,G_MPa,nu_phi_r,level,nodes,elements,"
             "load_contact_N,load_section_N,ccx_seconds"]
    profiles = ["alpha,material,level,r_mm,sigma_r_0_MPa,sigma_phi_0_MPa,sigma_r_90_MPa,"
                "sigma_phi_90_MPa"]
    for alpha in ALPHAS:
        for material in MATERIALS:
            for level in args.levels:
                res = run_case(alpha, material, level, workdir)
                e_r, e_phi, g = MATERIALS[material]
                print("%-26s nodes %6d  P %.9g N (section %.9g)  ccx %.2f s" %
                      (res["job"], res["nodes"], res["load_contact"], res["load_section"],
                       res["seconds"]))
                loads.append("%g,%s,%.10g,%.10g,%.10g,%g,%d,%d,%d,%.9e,%.9e,%.3f" %
                             (alpha, material, e_r, e_phi, g, NU_PHI_R, level, res["nodes"],
                              res["elements"], res["load_contact"], res["load_section"],
                              res["seconds"]))
                for row in res["profile"]:
                    profiles.append("%g,%s,%d,%.12g,%.6e,%.6e,%.6e,%.6e" %
                                    ((alpha, material, level) + row))
    with open(os.path.join(args.out, "loads.csv"), "w") as f:
        f.write("\n".join(loads) + "\n")
    with open(os.path.join(args.out, "profiles.csv"), "w") as f:
        f.write("\n".join(profiles) + "\n")
    if not args.keep:
        shutil.rmtree(workdir)


if __name__ == "__main__":
    main()
