#!/usr/bin/env python3
"""Independent reference for the pocket-wheel run-on of seed 003 (Python 3 standard library only).

Shares no code and no closed form with Catena. The formulation is a link-by-link closure:

* the pitch radius R is the root (bisection) of the polygon's closure: z links of length t + d
  and z of length t - d, alternating, are chords of one circle that close after one turn
  (the geometry of 003 eqs. 6-9, but not eq. (6) itself);
* a joint that lands on the wheel is fixed to it and turns with it (clockwise, angle phi);
* the free span of the strand is taut and straight; for the guided run-on it runs from the last
  seated joint (the crank) to the material point of the chain that lay at the guide end x = -l
  at phi = 0 (the paper's slider reading, eqs. 14-17, 26-35), and that point stays on the guide
  line y = H; its abscissa is found by bisection of |P - crank| = span;
  for free run-on the strand stays horizontal and moves with the crank;
* the next free joint lies on the span at one link length (t + d or t - d) from the crank; it
  seats when its distance from the axis equals R, found by scanning and bisection; it is then
  fixed to the wheel where it landed, and the span shortens by that link;
* velocity and acceleration are fourth-order central finite differences IN TIME of the solved
  positions (the topology of the phase held fixed across the stencil).

Initial state (phi = 0): the crank is where the guide line meets the pitch circle on the guide
side; chordal: the guide line is the chord of a seated t + d link (found from the circle, not from
eq. 7), the next link to seat is t - d; tangential: the crank is at the top (0, R), the next link
is t + d; free: the crank has just seated its t + d link, horizontal strand, next link t - d.

Usage: python3 generate.py [outdir]   (writes run_on.csv, events.csv; prints accuracy estimates)
"""

import math
import sys

# The seed's example (003 §2-3): chain 18 x 64, z = 8, omega = 5 1/s, guide end l = 0.256 m.
T = 0.064  # [m] pitch t
D = 0.018  # [m] wire diameter d
Z = 8  # [-] teeth (pockets)
OMEGA = 5.0  # [rad/s]
L_GUIDE = 0.256  # [m] guide end abscissa from the wheel axis
SAMPLES = 65  # phi_k = k * (2 pi / z) / 64, k = 0 .. 64 (the last one is the left limit)
STEP_PHI = 4e-3  # [rad] finite-difference step in phi (time step STEP_PHI / OMEGA)


def bisect(f, a, b):
    """Root of f in [a, b] (f(a), f(b) of opposite sign) to the last representable bit."""
    fa = f(a)
    fb = f(b)
    if fa == 0.0:
        return a
    if fb == 0.0:
        return b
    if (fa > 0) == (fb > 0):
        raise ValueError("root not bracketed: f(%r)=%r f(%r)=%r" % (a, fa, b, fb))
    while True:
        m = 0.5 * (a + b)
        if m <= min(a, b) or m >= max(a, b):
            return m
        fm = f(m)
        if fm == 0.0:
            return m
        if (fm > 0) == (fa > 0):
            a, fa = m, fm
        else:
            b = m


def pitch_radius():
    """R such that the 2z alternating chords t + d, t - d close after one turn."""

    def turn_excess(r):
        # central angle of a chord c on a circle of radius r, summed over the 2z links, minus 2 pi
        return Z * (2 * math.asin((T + D) / (2 * r)) + 2 * math.asin((T - D) / (2 * r))) - 2 * math.pi

    lo = (T + D) / 2 * (1 + 1e-15)  # the longest chord must fit: r >= (t + d)/2
    hi = 10.0 * Z * T  # far too large: the chords subtend too little
    return bisect(turn_excess, lo, hi)


def rotate(p, a):
    """Turn point p clockwise by angle a about the axis (the wheel's sense of rotation)."""
    c, s = math.cos(a), math.sin(a)
    return (p[0] * c + p[1] * s, -p[0] * s + p[1] * c)


class Phase:
    def __init__(self, begin, crank_at_begin, span, next_link):
        self.begin = begin  # [rad]
        self.crank0 = crank_at_begin  # [m] crank position at phi = begin
        self.span = span  # [m] strand length from the crank to the tracked material point
        self.next_link = next_link  # [m] link between the crank and the next free joint
        self.end = None


class RunOn:
    def __init__(self, kind, radius):
        self.kind = kind
        self.r = radius
        self.period = 2 * math.pi / Z
        if kind == "none":
            # crank: upstream end of a horizontal seated t + d chord
            half = (T + D) / 2
            crank = (-half, math.sqrt(radius * radius - half * half))
            links = [T - D, T + D]
            self.h = None
        elif kind == "chordal":
            # the guide line is the line of a seated t + d chord: y = H with chord length t + d
            half = (T + D) / 2
            self.h = bisect(lambda y: 2 * math.sqrt(radius * radius - y * y) - (T + D), 0.0, radius)
            crank = (-math.sqrt(radius * radius - self.h * self.h), self.h)
            links = [T - D, T + D]
        elif kind == "tangential":
            self.h = radius
            crank = (0.0, radius)
            links = [T + D, T - D]
        else:
            raise ValueError(kind)
        # the tracked material point starts at x = -l (free: a point of the strand at -l)
        span0 = crank[0] + L_GUIDE if kind == "none" else math.hypot(crank[0] + L_GUIDE, crank[1] - self.h)
        self.phases = [Phase(0.0, crank, span0, links[0])]
        k = 0
        while True:
            ph = self.phases[-1]
            ev = self._find_seating(ph)
            if ev is None:
                ph.end = self.period
                break
            ph.end = ev
            k += 1
            landed = self._next_joint(ph, ev)
            self.phases.append(Phase(ev, landed, ph.span - ph.next_link, links[k % 2]))

    def crank(self, ph, phi):
        return rotate(ph.crank0, phi - ph.begin)

    def tracked_point(self, ph, phi):
        """Position of the tracked material point of the strand."""
        c = self.crank(ph, phi)
        if self.kind == "none":
            return (c[0] - ph.span, c[1])
        # on y = H, upstream of the crank, at distance span: bisection on its abscissa
        dy = c[1] - self.h
        f = lambda xp: math.hypot(c[0] - xp, dy) - ph.span
        return (bisect(f, c[0] - ph.span * (1 + 1e-12) - 1e-12, c[0]), self.h)

    def _next_joint(self, ph, phi):
        c = self.crank(ph, phi)
        p = self.tracked_point(ph, phi)
        n = math.hypot(p[0] - c[0], p[1] - c[1])
        return (c[0] + ph.next_link * (p[0] - c[0]) / n, c[1] + ph.next_link * (p[1] - c[1]) / n)

    def _find_seating(self, ph):
        g = lambda phi: math.hypot(*self._next_joint(ph, phi)) - self.r
        n = 4000
        a = ph.begin
        ga = g(a + 1e-12)
        stop = self.period * (1 - 1e-9)
        for i in range(1, n + 1):
            b = ph.begin + (stop - ph.begin) * i / n
            gb = g(b)
            if ga > 0 and gb <= 0:
                return bisect(g, a, b)
            a, ga = b, gb
        return None

    def phase_at(self, phi):
        for i, ph in enumerate(self.phases):
            if phi < ph.end or i == len(self.phases) - 1:
                return ph
        return self.phases[-1]

    def position(self, ph, phi):
        """(x, y): x travel of the tracked point since phi = 0; y of the crank (free run-on)."""
        p = self.tracked_point(ph, phi)
        return (p[0] + L_GUIDE, self.crank(ph, phi)[1])


def derivatives(run, ph, phi, h_phi):
    """x, v_x, a_x (and y, v_y, a_y) at phi by 4th-order central differences in time."""
    h = h_phi / OMEGA  # [s]
    tau = phi / OMEGA
    pos = [run.position(ph, (tau + j * h) * OMEGA) for j in (-2, -1, 0, 1, 2)]
    out = []
    for c in (0, 1):
        f = [q[c] for q in pos]
        v = (f[0] - 8 * f[1] + 8 * f[3] - f[4]) / (12 * h)
        a = (-f[0] + 16 * f[1] - 30 * f[2] + 16 * f[3] - f[4]) / (12 * h * h)
        out.append((f[2], v, a))
    return out


def main():
    outdir = sys.argv[1] if len(sys.argv) > 1 else "."
    r = pitch_radius()
    runs = {k: RunOn(k, r) for k in ("none", "chordal", "tangential")}
    period = 2 * math.pi / Z
    rows = []
    worst = {"vx": 0.0, "ax": 0.0}
    for k in range(SAMPLES):
        phi = period * k / (SAMPLES - 1)
        row = [phi, phi / OMEGA]
        for name, run in runs.items():
            # right-hand limit at an event; the last sample (phi = 2 pi / z) is the LEFT limit
            ph = run.phase_at(phi) if k < SAMPLES - 1 else run.phases[-1]
            (x, vx, ax), (y, vy, ay) = derivatives(run, ph, phi, STEP_PHI)
            # Richardson-type error estimate: the same stencil with twice the step
            (_, vx2, ax2), _ = derivatives(run, ph, phi, 2 * STEP_PHI)
            worst["vx"] = max(worst["vx"], abs(vx2 - vx) / 15)
            worst["ax"] = max(worst["ax"], abs(ax2 - ax) / 15)
            row += [x, vx, ax]
            if name == "none":
                row += [vy, ay]
        rows.append(row)
    header = ("phi,time,x_none,vx_none,ax_none,vy_none,ay_none,"
              "x_chordal,vx_chordal,ax_chordal,x_tangential,vx_tangential,ax_tangential")
    with open(outdir + "/run_on.csv", "w") as f:
        f.write("# generated by generate.py (independent link-by-link closure); see README.md\n")
        f.write(header + "\n")
        for row in rows:
            f.write(",".join(repr(v) for v in row) + "\n")
    with open(outdir + "/events.csv", "w") as f:
        f.write("# generated by generate.py; seating events in (0, 2 pi/z) and the pitch radius\n")
        f.write("guide,quantity,value\n")
        f.write("all,pitch_radius_m,%r\n" % r)
        for name, run in runs.items():
            if run.h is not None:
                f.write("%s,guide_height_m,%r\n" % (name, run.h))
            for i, ph in enumerate(run.phases[1:]):
                f.write("%s,seating_rad_%d,%r\n" % (name, i + 1, ph.begin))
            last = run.phases[-1]
            f.write("%s,x_end_of_period_m,%r\n" % (name, run.position(last, period)[0]))
    print("R = %.15g m" % r)
    for name, run in runs.items():
        print(name, "seatings [deg]:", [math.degrees(p.begin) for p in run.phases[1:]],
              "x(2pi/z-) =", run.position(run.phases[-1], period)[0])
    print("finite-difference error estimate (|h - 2h| / 15): vx %.2e m/s, ax %.2e m/s^2"
          % (worst["vx"], worst["ax"]))


if __name__ == "__main__":
    main()
