#!/usr/bin/env python3
"""Time-optimal bound of a programmed feed path: lines, arcs and helices as the canonical trace
writes them, run from rest to rest within the feed and each axis's velocity, acceleration and
jerk limits, within the path tolerance at the corners.

The integration is shared/tools/motion/bounds.py's (topp_acc), generalised to a chain of elements
with a velocity cap per point: along p(s) axis i moves with a_i = u_i s'' + n_i s'^2; the maximum
velocity curve (MVC) is the largest s'^2 for which some s'' keeps every |a_i| <= A_i (closed form
here: one linear inequality per pair of axes), clipped to the feed and the axis velocities;
forward integration of the largest s'' from rest and backward integration of the smallest s''
from rest at the end give upper envelopes of every feasible profile, and the time along
min(forward, backward) is the bound of the acceleration-limited motion. The jerk adds A/J (the
two jerk-limited rest ramps of a straight line), as in bounds.py.

Exact along the elements (tangent joins pass at any speed their curves allow; a step of
curvature costs nothing, which only lowers the bound). A corner (a join turning by theta > 0.05
degrees) is where the tolerance delta (the machine's path_tolerance; the planner gives half of it
to its blend, half to the servo filter) lets the motion leave the programmed path; two models:
- free: the corner costs nothing (the path turns at any speed). Below the true optimum.
- band (the bound this module reports by default): the speed at the corner is at most the speed
  at the apex of the fastest turn with a constant acceleration a_d along the bisector's normal
  d = (u2 - u1) / |u2 - u1| (a_d = min_i A_i / |d_i|) that fits in the +-delta band about the
  two moves: from the outer edge of the band along the move before, through the band's inner
  corner, to the outer edge along the move after. It enters at v, v^2 = 4 a_d delta /
  (cos(theta/2) sin^2(theta/2)), and passes the corner at v cos(theta/2), where the bound caps
  the speed (the bound then brakes and accelerates along the moves, at their own limits). On a
  90-degree corner along the axes this is 12.6 mm/s with the mill's A 2000 and delta 0.01, where
  the fastest turn (each axis at its full acceleration: X stops while Y starts) passes at
  12.6 mm/s after entering at 17.9 mm/s, and the bound's brake-and-accelerate is 2-3 ms faster
  than that turn; a reversal (theta -> 180) stops. The band is used whole, on both sides of the
  path, twice what the planner's blend takes (the other half is its filter's): a model of the
  optimum, not a proof.
Both let the motion cut across a sharp corner where the two lines are within 2 delta of each
other (_trims): the programmed length is not a lower bound there.
"""
import math

TANGENT_RAD = math.radians(0.05)


class Element:
    """One programmed move: p(s), the unit tangent u(s) and n(s) = d2p/ds2 by arc length."""

    def __init__(self, start, end, cap, centre=None, plane=None, sweep=0.0):
        self.start, self.end, self.cap = start, end, cap
        if centre is None:
            self.arc = False
            self.length = math.dist(start, end)
            return
        self.arc = True
        a, b = plane  # the plane's axes (indices), counter-clockwise from a to b
        axial = 3 - a - b
        self.a, self.b, self.axial = a, b, axial
        self.ca, self.cb = centre
        self.radius = math.hypot(start[a] - self.ca, start[b] - self.cb)
        self.phi0 = math.atan2(start[b] - self.cb, start[a] - self.ca)
        self.sweep = sweep
        self.rise = end[axial] - start[axial]
        self.length = math.hypot(self.radius * sweep, self.rise)

    def frame(self, s):
        """(u, n) at arc length s."""
        if not self.arc:
            if self.length <= 0.0:
                return (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)
            u = tuple((e - b) / self.length for e, b in zip(self.end, self.start))
            return u, (0.0, 0.0, 0.0)
        k = self.sweep / self.length  # radians per mm of path
        phi = self.phi0 + k * s
        u, n = [0.0] * 3, [0.0] * 3
        u[self.a] = -self.radius * k * math.sin(phi)
        u[self.b] = self.radius * k * math.cos(phi)
        u[self.axial] = self.rise / self.length
        n[self.a] = -self.radius * k * k * math.cos(phi)
        n[self.b] = -self.radius * k * k * math.sin(phi)
        return tuple(u), tuple(n)

    def point(self, s):
        if not self.arc:
            t = s / self.length if self.length > 0 else 0.0
            return tuple(b + (e - b) * t for b, e in zip(self.start, self.end))
        phi = self.phi0 + self.sweep * s / self.length
        p = [0.0] * 3
        p[self.a] = self.ca + self.radius * math.cos(phi)
        p[self.b] = self.cb + self.radius * math.sin(phi)
        p[self.axial] = self.start[self.axial] + self.rise * s / self.length
        return tuple(p)


class Limits:
    def __init__(self, velocity, accel, jerk, tolerance):
        self.velocity, self.accel, self.jerk, self.tolerance = velocity, accel, jerk, tolerance


def _mvc(u, n, cap2, lim):
    """The largest s'^2 at which some s'' keeps every axis within its acceleration."""
    x = cap2
    moving = []
    for i in range(3):
        if abs(u[i]) > 1e-12:
            x = min(x, (lim.velocity[i] / abs(u[i])) ** 2)
            moving.append(i)
        elif abs(n[i]) > 1e-12:
            x = min(x, lim.accel[i] / abs(n[i]))
    # s'' must lie in [-A_i/|u_i| - (n_i/u_i) x, A_i/|u_i| - (n_i/u_i) x] for every moving axis
    for i in moving:
        for j in moving:
            if i == j:
                continue
            c = n[j] / u[j] - n[i] / u[i]
            if c > 1e-15:
                x = min(x, (lim.accel[i] / abs(u[i]) + lim.accel[j] / abs(u[j])) / c)
    return max(x, 0.0)


def _sdd_range(u, n, x, lim):
    lo, hi = -1e300, 1e300
    for i in range(3):
        if abs(u[i]) <= 1e-12:
            continue
        a = (-lim.accel[i] - n[i] * x) / u[i]
        b = (lim.accel[i] - n[i] * x) / u[i]
        if a > b:
            a, b = b, a
        lo, hi = max(lo, a), min(hi, b)
    return lo, hi


def corner_cap2(u1, u2, lim):
    """The band model's s'^2 at a corner from direction u1 to u2 (None: tangent)."""
    theta = _turn(u1, u2)
    if theta < TANGENT_RAD:
        return None
    diff = [b - a for a, b in zip(u1, u2)]
    norm = math.sqrt(sum(c * c for c in diff))
    a_d = min(lim.accel[i] / abs(diff[i] / norm) for i in range(3) if abs(diff[i]) > 1e-12)
    half = theta / 2
    return 4.0 * a_d * lim.tolerance * math.cos(half) / math.sin(half) ** 2


def _turn(u1, u2):
    return math.acos(max(-1.0, min(1.0, sum(a * b for a, b in zip(u1, u2)))))


def _trims(elements, lim):
    """How much of each line's start and end a corner lets the motion cut: where the lines before
    and after a corner of theta are within 2 delta of each other, up to delta / cos(theta/2) from
    the vertex (0.06 mm at a 170-degree reciprocating plunge), the motion may go straight across
    (at most half of each line)."""
    cut = [[0.0, 0.0] for _ in elements]
    for k in range(1, len(elements)):
        a, b = elements[k - 1], elements[k]
        if a.arc or b.arc:
            continue
        theta = _turn(a.frame(a.length)[0], b.frame(0.0)[0])
        if theta < TANGENT_RAD:
            continue
        reach = lim.tolerance / max(math.cos(theta / 2), 1e-9)
        cut[k - 1][1] = min(reach, a.length / 2)
        cut[k][0] = min(reach, b.length / 2)
    return cut


def _samples(elements, lim, corners, step):
    """Per sample: the element's u, n, the MVC, the distance to the next sample and the index of
    the element in `elements`."""
    us, ns, mvc, ds, owner = [], [], [], [], []
    previous_u = None
    moving = [k for k, e in enumerate(elements) if e.length > 1e-9]
    elements = [elements[k] for k in moving]
    for index, e, (cut_start, cut_end) in zip(moving, elements, _trims(elements, lim)):
        length = e.length - cut_start - cut_end
        h = step if not e.arc else min(step, e.radius * math.radians(2.0))
        count = max(1, int(math.ceil(length / h)))
        h = length / count
        for k in range(count + 1):
            s = cut_start + k * h
            u, n = e.frame(s)
            cap = e.cap(e.point(s))
            x = _mvc(u, n, cap * cap, lim)
            if k == 0 and previous_u is not None and corners:
                c = corner_cap2(previous_u, u, lim)
                if c is not None:
                    x = min(x, c)
                    mvc[-1] = min(mvc[-1], c)
            us.append(u)
            ns.append(n)
            mvc.append(x)
            ds.append(h if k < count else 0.0)
            owner.append(index)
        previous_u = us[-1]
    return us, ns, mvc, ds, owner


def rest_to_rest_time(elements, lim, corners=True, step=0.05):
    """The bound (s) of one run of feed moves from rest to rest: acceleration part + A/J."""
    return sum(element_times(elements, lim, corners, step)) + max(lim.accel) / min(lim.jerk)


def element_times(elements, lim, corners=True, step=0.05):
    """The acceleration-limited part of the bound, per element (to see where a run loses time)."""
    times = [0.0] * len(elements)
    us, ns, mvc, ds, owner = _samples(elements, lim, corners, step)
    count = len(mvc)
    if count < 2:
        return times
    fwd = [0.0] * count
    for k in range(count - 1):
        h = ds[k]
        if h == 0.0:
            fwd[k + 1] = min(fwd[k], mvc[k + 1])
            continue
        x = fwd[k]
        _, h1 = _sdd_range(us[k], ns[k], x, lim)
        xm = max(0.0, min(x + 2.0 * h1 * h, mvc[k + 1]))
        _, h2 = _sdd_range(us[k + 1], ns[k + 1], xm, lim)
        fwd[k + 1] = max(0.0, min(x + (h1 + h2) * h, mvc[k + 1]))
    bwd = [0.0] * count
    for k in range(count - 1, 0, -1):
        h = ds[k - 1]
        if h == 0.0:
            bwd[k - 1] = min(bwd[k], mvc[k - 1])
            continue
        x = bwd[k]
        l1, _ = _sdd_range(us[k], ns[k], x, lim)
        xm = max(0.0, min(x - 2.0 * l1 * h, mvc[k - 1]))
        l2, _ = _sdd_range(us[k - 1], ns[k - 1], xm, lim)
        bwd[k - 1] = max(0.0, min(x - (l1 + l2) * h, mvc[k - 1]))
    for k in range(count - 1):
        h = ds[k]
        if h == 0.0:
            continue
        x0, x1 = min(fwd[k], bwd[k]), min(fwd[k + 1], bwd[k + 1])
        # The fastest way from x0 to x1 within the step: change the speed at the largest s''
        # the two ends allow, and run the rest of the step at the higher speed (a step that
        # reaches the feed after 0.001 mm of 0.05 mm is not an acceleration along all of it).
        here, there = _sdd_range(us[k], ns[k], x0, lim), _sdd_range(us[k + 1], ns[k + 1], x1, lim)
        a = max(here[1], there[1]) if x1 >= x0 else -min(here[0], there[0])
        v0, v1 = math.sqrt(x0), math.sqrt(x1)
        ramp = abs(x1 - x0) / (2.0 * a) if a > 0.0 else h
        if ramp < h:
            times[owner[k]] += abs(v1 - v0) / a + (h - ramp) / max(v0, v1)
        elif v0 + v1 > 0.0:
            times[owner[k]] += 2.0 * h / (v0 + v1)  # exact for a constant s'' over the step
    return times
