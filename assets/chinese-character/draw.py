#!/usr/bin/env python3
"""Chinese character: draws the two keys, 八 (ba, eight) and 人 (ren, person), as brush strokes
(vermilion fill, ink outline, dry-brush streaks of paper tint) and writes scene.json. Both are
the same two strokes, the left-falling pie and the right-falling na; in 八 they stand apart, in
人 the na starts on the pie, so a split cut along that join (closed in 人) lets them come apart.
Rasterize with
  rsvg-convert -w 512 -h 512 ba.svg -o ba.png; rsvg-convert -w 512 -h 512 ren.svg -o ren.png
Drawings: made for this project, CC0 1.0.
"""
import json, math, os

HERE = os.path.dirname(os.path.abspath(__file__))
INK, FILL, PAPER, WASH = "#2a0c05", "#c23b22", "#f3e6c8", "#e3906f"  # outline, vermilion, paper, wash

def bez(p0, p1, p2, t):
    return ((1 - t) ** 2 * p0[0] + 2 * (1 - t) * t * p1[0] + t ** 2 * p2[0],
            (1 - t) ** 2 * p0[1] + 2 * (1 - t) * t * p1[1] + t ** 2 * p2[1])

def stroke(path, widths, n=48):
    """Outline polygon of a brush stroke along a polyline of quadratic pieces
    [(p0, p1, p2), ...]; widths(t) gives the width at t in [0, 1] along the whole stroke.
    Round ends."""
    pts = []
    for j, (p0, p1, p2) in enumerate(path):
        for k in range(n + (1 if j == len(path) - 1 else 0)):
            pts.append(bez(p0, p1, p2, k / n))
    m = len(pts)
    L, R = [], []
    for i, p in enumerate(pts):
        a, b = pts[max(i - 1, 0)], pts[min(i + 1, m - 1)]
        dx, dy = b[0] - a[0], b[1] - a[1]
        d = math.hypot(dx, dy) or 1.0
        nx, ny = -dy / d, dx / d
        w = widths(i / (m - 1)) / 2
        L.append((p[0] + nx * w, p[1] + ny * w))
        R.append((p[0] - nx * w, p[1] - ny * w))
    def cap(c, frm, to, fwd, steps=12):
        """Half-turn round cap from frm to to about c, bulging along fwd."""
        a0 = math.atan2(frm[1] - c[1], frm[0] - c[0])
        af = math.atan2(fwd[1], fwd[0])
        da = math.pi if ((af - a0) % (2 * math.pi)) < math.pi else -math.pi
        r = math.hypot(frm[0] - c[0], frm[1] - c[1])
        return [(c[0] + r * math.cos(a0 + da * s / steps), c[1] + r * math.sin(a0 + da * s / steps))
                for s in range(1, steps)]
    fe = (pts[-1][0] - pts[-2][0], pts[-1][1] - pts[-2][1])
    fs = (pts[0][0] - pts[1][0], pts[0][1] - pts[1][1])
    poly = L + cap(pts[-1], L[-1], R[-1], fe) + R[::-1] + cap(pts[0], R[0], L[0], fs)
    return poly, pts

def d_of(poly):
    return "M" + " L".join("%.1f,%.1f" % p for p in poly) + " Z"

def hairs(pts, widths, offs):
    out = []
    m = len(pts)
    for f in offs:
        q = []
        for i in range(2, m - 2):
            a, b = pts[i - 1], pts[i + 1]
            dx, dy = b[0] - a[0], b[1] - a[1]
            d = math.hypot(dx, dy) or 1.0
            w = widths(i / (m - 1)) / 2
            q.append((pts[i][0] - dy / d * w * f, pts[i][1] + dx / d * w * f))
        out.append("M" + " L".join("%.1f,%.1f" % p for p in q))
    return out

def press(t, w0, w1, w2):
    """A brush stroke's width: pressed at the start (w0), w1 along, w2 at the end."""
    if t < 0.12:
        return w0 + (w1 - w0) * (t / 0.12)
    if t > 0.85:
        return w1 + (w2 - w1) * ((t - 0.85) / 0.15)
    return w1


def pie_w(t):      # left-falling stroke: pressed head, tapering to a thin (but traceable) tail
    return 58 if t < 0.06 else (58 - (58 - 44) * (t - 0.06) / 0.14 if t < 0.2 else 44 - 24 * ((t - 0.2) / 0.8) ** 1.2)

def na_w(t):       # right-falling stroke: light start, swelling to the foot, flicked out
    if t < 0.8:
        return 24 + 30 * (t / 0.8) ** 1.5
    return 54 - 28 * ((t - 0.8) / 0.2)

def seg_x(a, b, c, d):
    (x1, y1), (x2, y2), (x3, y3), (x4, y4) = a, b, c, d
    den = (x1 - x2) * (y3 - y4) - (y1 - y2) * (x3 - x4)
    if abs(den) < 1e-12:
        return None
    t = ((x1 - x3) * (y3 - y4) - (y1 - y3) * (x3 - x4)) / den
    u = -((x1 - x2) * (y1 - y3) - (y1 - y2) * (x1 - x3)) / den
    if 0 <= t <= 1 and 0 <= u <= 1:
        return (x1 + t * (x2 - x1), y1 + t * (y2 - y1))
    return None

def crossings(P, Q):
    out = []
    for i in range(len(P)):
        for j in range(len(Q)):
            x = seg_x(P[i], P[(i + 1) % len(P)], Q[j], Q[(j + 1) % len(Q)])
            if x:
                out.append(x)
    return out

def character(name, pie, na):
    S = [(pie, pie_w), (na, na_w)]
    polys = [stroke(p, w) for p, w in S]
    o = ['<svg xmlns="http://www.w3.org/2000/svg" width="512" height="512" viewBox="0 0 512 512">',
         '  <!-- %s as brush strokes, drawn for inbetween (CC0 1.0) by draw.py -->' % name]
    for poly, _ in polys:
        o.append('  <path d="%s" fill="%s" stroke="%s" stroke-width="12" stroke-linejoin="round"/>' % (d_of(poly), INK, INK))
    for (poly, pts), (p, w) in zip(polys, S):
        o.append('  <path d="%s" fill="%s"/>' % (d_of(poly), FILL))
    for (poly, pts), (p, w) in zip(polys, S):
        # dry-brush streaks ("flying white"): paper showing through, opaque
        for k, h in enumerate(hairs(pts, w, (-0.5, 0.12, 0.52))):
            col = PAPER if k != 1 else WASH
            o.append('  <path d="%s" fill="none" stroke="%s" stroke-width="%d" stroke-linecap="round"/>' % (h, col, 4 if k != 1 else 7))
    o.append('</svg>')
    return "\n".join(o) + "\n", polys

# 八: the strokes lean apart; 人: the na starts on the pie's right side
BA = ([((216, 128), (212, 330), (84, 432))],
      [((300, 150), (322, 330), (408, 404)), ((408, 404), (432, 424), (468, 420))])
REN = ([((268, 84), (262, 320), (98, 446))],
       [((254, 234), (330, 350), (404, 418)), ((404, 418), (432, 432), (470, 426))])

def tip(pts, wf):
    a, b = pts[-2], pts[-1]
    dx, dy = b[0] - a[0], b[1] - a[1]; d = math.hypot(dx, dy)
    w = wf(1.0) / 2 + 6
    return (b[0] + dx / d * w, b[1] + dy / d * w)

def r(p):
    return [round(p[0], 1), round(p[1], 1)]

def main():
    t_ba, p_ba = character("ba", *BA)
    t_ren, p_ren = character("ren", *REN)
    for n, t in (("ba", t_ba), ("ren", t_ren)):
        with open(os.path.join(HERE, n + ".svg"), "w") as f:
            f.write(t)
    # the join in 人: from corner to corner, where the na's ink outline crosses the pie's
    # (the notch above the na's head and the V below it), so that every end is a corner of the
    # outline and the cut leaves it at a wide angle
    ink = lambda k: [stroke(p, lambda t, w=w: w(t) + 12)[0] for p, w in ((k[0], pie_w), (k[1], na_w))]
    xs = sorted(crossings(*ink(REN)), key=lambda p: p[1])
    up, lo = xs[0], xs[-1]
    cut = [r(up), r(lo)]
    # 八: the na's head (its start cap) and the stretch of the pie's right edge facing it
    na_pts = p_ba[1][1]; pie_pts = p_ba[0][1]
    h0 = na_pts[0]
    def edge1(pts, wf, i, side):  # the ink outline beside centre-line point i
        a, b = pts[max(i - 1, 0)], pts[min(i + 1, len(pts) - 1)]
        dx, dy = b[0] - a[0], b[1] - a[1]; d = math.hypot(dx, dy)
        w = wf(i / (len(pts) - 1)) / 2 + 6
        return (pts[i][0] - side * dy / d * w, pts[i][1] + side * dx / d * w)
    def edge(pts, wf, t, side):   # ... at t in [0, 1], between the points
        s = t * (len(pts) - 1); i = min(int(s), len(pts) - 2); f = s - i
        p, q = edge1(pts, wf, i, side), edge1(pts, wf, i + 1, side)
        return (p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1]))
    ren_pie = p_ren[0][1]
    def t_on(p):                 # the pie's parameter whose right edge point is nearest p
        return min((k / 2000 for k in range(2001)), key=lambda t: math.dist(edge(ren_pie, pie_w, t, -1), p))
    t_up, t_lo = t_on(up), t_on(lo)
    feats_ba = {"pie-head": r((pie_pts[0][0], pie_pts[0][1] - pie_w(0) / 2 - 6)),
                "pie-tail": r(tip(pie_pts, pie_w)), "na-tail": r(tip(na_pts, na_w)),
                "join.start.left": r(edge(na_pts, na_w, 0.0, -1)), "join.end.left": r(edge(na_pts, na_w, 0.0, 1)),
                "join.start.right": r(edge(pie_pts, pie_w, t_up, -1)), "join.end.right": r(edge(pie_pts, pie_w, t_lo, -1))}
    ren_pie = p_ren[0][1]; ren_na = p_ren[1][1]
    feats_ren = {"pie-head": r((ren_pie[0][0], ren_pie[0][1] - pie_w(0) / 2 - 6)),
                 "pie-tail": r(tip(ren_pie, pie_w)), "na-tail": r(tip(ren_na, na_w))}
    scene = {"version": 1, "reference": "ren", "edge_length": 11,
             "solver": {"alpha": 0.5, "tau": 3e-07},
             "keys": [
                 {"name": "ba", "drawing": "ba.png", "features": feats_ba},
                 {"name": "ren", "drawing": "ren.png", "features": feats_ren,
                  "cuts": [{"name": "join", "kind": "split", "points": cut}]}],
             "timeline": {"fps": 24, "loop": True, "marks": [
                 {"time": 0, "key": "ba", "ease": "ease-in-out"},
                 {"time": 0.4, "key": "ba", "ease": "ease-in-out"},
                 {"time": 1.4, "key": "ren", "ease": "ease-in-out"},
                 {"time": 1.8, "key": "ren", "ease": "ease-in-out"},
                 {"time": 2.8, "key": "ba"}]}}
    with open(os.path.join(HERE, "scene.json"), "w") as f:
        f.write(json.dumps(scene, indent=1) + "\n")

main()
