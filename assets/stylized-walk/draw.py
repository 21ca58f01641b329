#!/usr/bin/env python3
"""Stylized walk: draws the 16 keys (kNN.svg) of a bean character marching in place, seen from
the front, and writes scene.json. Each key poses the legs and arms by angle from the cycle's
phase i/16. Rasterize with
  for f in k*.svg; do rsvg-convert -w 512 -h 512 $f -o ${f%.svg}.png; done
Drawings: made for this project, CC0 1.0.
"""
import json, math, os

HERE = os.path.dirname(os.path.abspath(__file__))
N = 16
INK = "#1f2433"
BODY, BELLY, PANTS, SOCK, SHOE, GLOVE = "#45b58f", "#c9f0da", "#3b5fa8", "#f2c14e", "#e0483a", "#ffffff"
GROUND = 458.0          # bottom of the planted shoes
HIP_DX, FOOT_DX = 40.0, 46.0
THIGH = SHIN = 56.0
UPPER, FORE = 50.0, 44.0
RX, RY = 84.0, 104.0    # the bean body
JUNCTIONS = False       # outline features where the limbs meet the body (tried: no better)

def P(x, y):
    return "%.1f,%.1f" % (x, y)

def rot(x, y, a, cx, cy):
    a = math.radians(a)
    dx, dy = x - cx, y - cy
    return (cx + dx * math.cos(a) - dy * math.sin(a), cy + dx * math.sin(a) + dy * math.cos(a))

def knee(h, a, out):
    """Knee of a two-segment leg from hip h to ankle a, bent outwards (out = +1 / -1)."""
    dx, dy = a[0] - h[0], a[1] - h[1]
    d = math.hypot(dx, dy)
    d2 = min(d, 2 * THIGH - 0.5)
    b = math.sqrt(max(THIGH ** 2 - (d2 / 2) ** 2, 0.0))
    m = (h[0] + dx / 2, h[1] + dy / 2)
    n = (-dy / d, dx / d)
    if n[0] * out < 0:
        n = (-n[0], -n[1])
    return (m[0] + n[0] * b, m[1] + n[1] * b)

def bean_x(y):
    """x (right side, body frame) of the bean's outline at height y, from its two right-hand
    cubic segments."""
    segs = [((0, -RY), (0.62 * RX, -RY), (RX, -0.55 * RY), (RX, 0.05 * RY)),
            ((RX, 0.05 * RY), (RX, 0.62 * RY), (0.55 * RX, RY), (0, RY))]
    best = None
    for p0, p1, p2, p3 in segs:
        for k in range(2001):
            t = k / 2000.0
            c = [(1 - t) ** 3, 3 * (1 - t) ** 2 * t, 3 * (1 - t) * t ** 2, t ** 3]
            x = sum(w * p[0] for w, p in zip(c, (p0, p1, p2, p3)))
            yy = sum(w * p[1] for w, p in zip(c, (p0, p1, p2, p3)))
            if best is None or abs(yy - y) < best[0]:
                best = (abs(yy - y), x)
    return best[1]

def bean_loop(n=2400):
    """The bean's outline, clockwise from the crown (body frame), offset 2.5 px outwards (the
    outer edge of its outline)."""
    segs = [((0, -RY), (0.62 * RX, -RY), (RX, -0.55 * RY), (RX, 0.05 * RY)),
            ((RX, 0.05 * RY), (RX, 0.62 * RY), (0.55 * RX, RY), (0, RY)),
            ((0, RY), (-0.55 * RX, RY), (-RX, 0.62 * RY), (-RX, 0.05 * RY)),
            ((-RX, 0.05 * RY), (-RX, -0.55 * RY), (-0.62 * RX, -RY), (0, -RY))]
    pts = []
    for p0, p1, p2, p3 in segs:
        for k in range(n // 4):
            t = k / (n / 4.0)
            c = [(1 - t) ** 3, 3 * (1 - t) ** 2 * t, 3 * (1 - t) * t ** 2, t ** 3]
            d = [-3 * (1 - t) ** 2, 3 * (1 - t) ** 2 - 6 * (1 - t) * t, 6 * (1 - t) * t - 3 * t ** 2, 3 * t ** 2]
            x = sum(w * p[0] for w, p in zip(c, (p0, p1, p2, p3)))
            y = sum(w * p[1] for w, p in zip(c, (p0, p1, p2, p3)))
            dx = sum(w * p[0] for w, p in zip(d, (p0, p1, p2, p3)))
            dy = sum(w * p[1] for w, p in zip(d, (p0, p1, p2, p3)))
            L = math.hypot(dx, dy) or 1.0
            pts.append((x - dy / L * 2.5, y + dx / L * 2.5))   # clockwise on screen: outward is (-dy, dx)
    return pts

def seg_dist(p, a, b):
    ax, ay = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, ((p[0] - a[0]) * ax + (p[1] - a[1]) * ay) / (ax * ax + ay * ay)))
    return math.hypot(p[0] - a[0] - t * ax, p[1] - a[1] - t * ay)

def junctions(B, legs, arms):
    """Where each limb's outline meets the body's (the concave corners at shoulders, armpits
    and hips), as outline features: walking the body's outline clockwise from the crown, the
    first and last points inside each limb."""
    loop = [B(x, y) for (x, y) in bean_loop()]
    limbs = {"armR": (arms["R"][:3], 15.0), "legR": (legs["R"][:3], 18.0),
             "legL": (legs["L"][:3], 18.0), "armL": (arms["L"][:3], 15.0)}
    names = {"armR": ("shoulderR", "armpitR"), "legR": ("hipRout", "hipRin"),
             "legL": ("hipLin", "hipLout"), "armL": ("armpitL", "shoulderL")}
    out = {}
    for limb, (pl, rad) in limbs.items():
        inside = [i for i, p in enumerate(loop)
                  if min(seg_dist(p, pl[0], pl[1]), seg_dist(p, pl[1], pl[2])) <= rad]
        def gap(i):
            p = loop[i % len(loop)]
            return min(seg_dist(p, pl[0], pl[1]), seg_dist(p, pl[1], pl[2])) - rad
        i0, i1 = inside[0], inside[-1]
        while gap(i0) < 1.5:      # narrow wedges close up in the raster: step to where they open
            i0 -= 1
        while gap(i1) < 1.5:
            i1 += 1
        a, b = loop[i0 % len(loop)], loop[i1 % len(loop)]
        out[names[limb][0]] = [round(a[0], 1), round(a[1], 1)]
        out[names[limb][1]] = [round(b[0], 1), round(b[1], 1)]
    return out

def pose(i):
    s = math.sin(2 * math.pi * i / N)
    liftL, liftR = max(0.0, s), max(0.0, -s)           # screen-left leg lifts first
    up = abs(s)
    cx = 256.0 + 10.0 * s                              # weight over the standing leg
    ankle_y = GROUND - 20.0
    # body height: the standing leg almost straight when the other is up, knees soft at contact
    hip_y = ankle_y - (2 * THIGH - 14.0 + 10.0 * up)
    cy = hip_y - 80.0
    tilt = 4.0 * s
    body = (cx, cy)
    def B(x, y):  # a point of the body frame (relative to the body centre), tilted
        return rot(cx + x, cy + y, tilt, cx, cy)
    legs = {}
    for side, lift in (("L", liftL), ("R", liftR)):
        sg = -1 if side == "L" else 1
        h = B(sg * HIP_DX, 80.0)
        a = (256.0 + sg * (FOOT_DX - 10.0 * lift), ankle_y - 58.0 * lift)
        k = knee(h, a, sg)
        legs[side] = (h, k, a, lift)
    arms = {}
    for side, raise_ in (("L", liftR), ("R", liftL)):   # the arm opposite the lifted leg pumps
        sg = -1 if side == "L" else 1
        sh = B(sg * 66.0, -30.0)
        a1 = math.radians(34.0 + 50.0 * raise_ + tilt * sg * 0.0)
        el = (sh[0] + sg * UPPER * math.sin(a1), sh[1] + UPPER * math.cos(a1))
        a2 = a1 + math.radians(10.0 + 70.0 * raise_)
        wr = (el[0] + sg * FORE * math.sin(a2), el[1] + FORE * math.cos(a2))
        arms[side] = (sh, el, wr, a2, sg)
    return body, tilt, B, legs, arms

def svg(i):
    body, tilt, B, legs, arms = pose(i)
    cx, cy = body
    o = ['<svg xmlns="http://www.w3.org/2000/svg" width="512" height="512" viewBox="0 0 512 512">',
         '  <!-- Stylized walk, key %d of 16, drawn for inbetween (CC0 1.0) by draw.py -->' % i]
    feats, inner = {}, {}
    # legs: dark line under a coloured line, sock stripe, shoe
    for side in ("L", "R"):
        h, k, a, lift = legs[side]
        d = "M%s L%s L%s" % (P(*h), P(*k), P(*a))
        o.append('  <path d="%s" fill="none" stroke="%s" stroke-width="36" stroke-linejoin="round" stroke-linecap="round"/>' % (d, INK))
        o.append('  <path d="%s" fill="none" stroke="%s" stroke-width="26" stroke-linejoin="round" stroke-linecap="round"/>' % (d, PANTS))
        # sock: the last 22 px of the shin
        L = math.hypot(a[0] - k[0], a[1] - k[1]); u = ((a[0] - k[0]) / L, (a[1] - k[1]) / L)
        s0 = (a[0] - u[0] * 24, a[1] - u[1] * 24)
        o.append('  <path d="M%s L%s" fill="none" stroke="%s" stroke-width="26"/>' % (P(*s0), P(*a), SOCK))
        s1 = (a[0] - u[0] * 14, a[1] - u[1] * 14)
        o.append('  <path d="M%s L%s" fill="none" stroke="%s" stroke-width="26"/>' % (P(*s1), P(a[0] - u[0] * 8, a[1] - u[1] * 8), SHOE))
        sg = -1 if side == "L" else 1
        fx, fy = a[0] + sg * 8, a[1] + 8
        ang = -sg * 12.0 * lift
        o.append('  <ellipse cx="%.1f" cy="%.1f" rx="30" ry="16" transform="rotate(%.1f %.1f %.1f)" fill="%s" stroke="%s" stroke-width="5"/>' % (fx, fy, ang, fx, fy, SHOE, INK))
        o.append('  <ellipse cx="%.1f" cy="%.1f" rx="12" ry="5" transform="rotate(%.1f %.1f %.1f)" fill="#ffb0a0"/>' % (fx + sg * 8, fy - 6, ang, fx, fy))
        bx, by = rot(fx, fy + 18.5, ang, fx, fy)
        feats["foot" + side] = [round(bx, 1), round(by, 1)]
    # arms
    for side in ("L", "R"):
        sh, el, wr, a2, sg = arms[side]
        d = "M%s L%s L%s" % (P(*sh), P(*el), P(*wr))
        o.append('  <path d="%s" fill="none" stroke="%s" stroke-width="30" stroke-linejoin="round" stroke-linecap="round"/>' % (d, INK))
        o.append('  <path d="%s" fill="none" stroke="%s" stroke-width="20" stroke-linejoin="round" stroke-linecap="round"/>' % (d, BODY))
        hx, hy = wr[0] + sg * 6 * math.sin(a2), wr[1] + 6 * math.cos(a2)
        o.append('  <circle cx="%.1f" cy="%.1f" r="17" fill="%s" stroke="%s" stroke-width="5"/>' % (hx, hy, GLOVE, INK))
        o.append('  <path d="M%s L%s" fill="none" stroke="%s" stroke-width="6" stroke-linecap="round"/>' % (
            P(hx - 8 * math.cos(a2), hy + 8 * math.sin(a2) * sg), P(hx + 8 * math.cos(a2), hy - 8 * math.sin(a2) * sg), "#b8c4d6"))
        ex, ey = hx + sg * 19.5 * math.sin(a2), hy + 19.5 * math.cos(a2)
        feats["hand" + side] = [round(ex, 1), round(ey, 1)]
        inner["palm" + side] = [round(hx, 1), round(hy, 1)]
    # body, tilted about its centre
    g = '  <g transform="rotate(%.2f %.1f %.1f)">' % (tilt, cx, cy)
    o.append(g)
    o.append('    <path d="M%s C%s %s %s C%s %s %s C%s %s %s C%s %s %s Z" fill="%s" stroke="%s" stroke-width="5"/>' % (
        P(cx, cy - RY),
        P(cx + 0.62 * RX, cy - RY), P(cx + RX, cy - 0.55 * RY), P(cx + RX, cy + 0.05 * RY),
        P(cx + RX, cy + 0.62 * RY), P(cx + 0.55 * RX, cy + RY), P(cx, cy + RY),
        P(cx - 0.55 * RX, cy + RY), P(cx - RX, cy + 0.62 * RY), P(cx - RX, cy + 0.05 * RY),
        P(cx - RX, cy - 0.55 * RY), P(cx - 0.62 * RX, cy - RY), P(cx, cy - RY), BODY, INK))
    # stripes over the top of the head (a knitted cap)
    o.append('    <path d="M%s Q%s %s" fill="none" stroke="#2f8a6c" stroke-width="8" stroke-linecap="round"/>' % (P(cx - 62, cy - 66), P(cx, cy - 92), P(cx + 62, cy - 66)))
    o.append('    <ellipse cx="%.1f" cy="%.1f" rx="50" ry="46" fill="%s"/>' % (cx, cy + 42, BELLY))
    for by in (28, 58):
        o.append('    <circle cx="%.1f" cy="%.1f" r="6" fill="%s"/>' % (cx, cy + by, INK))
    for ex in (-26, 26):
        o.append('    <ellipse cx="%.1f" cy="%.1f" rx="15" ry="19" fill="#ffffff" stroke="%s" stroke-width="4"/>' % (cx + ex, cy - 36, INK))
        o.append('    <circle cx="%.1f" cy="%.1f" r="7" fill="%s"/>' % (cx + ex + 2, cy - 33, INK))
        o.append('    <ellipse cx="%.1f" cy="%.1f" rx="10" ry="6" fill="#f08f8f"/>' % (cx + ex * 1.9, cy - 8))
    o.append('    <path d="M%s Q%s %s" fill="none" stroke="%s" stroke-width="5" stroke-linecap="round"/>' % (P(cx - 18, cy - 8), P(cx, cy + 6), P(cx + 18, cy - 8), INK))
    o.append('  </g>')
    o.append('</svg>')
    if JUNCTIONS:
        feats.update(junctions(B, legs, arms))
    for nm, (ex, ey) in (("crown", (0, -RY - 2.5)), ("seat", (0, RY + 2.5))):
        x, y = B(ex, ey)
        feats[nm] = [round(x, 1), round(y, 1)]
    for nm, (ex, ey) in (("eyeL", (-26, -36)), ("eyeR", (26, -36)),
                         ("cheekL", (-49, -8)), ("cheekR", (49, -8)), ("mouth", (0, 0)),
                         ("button1", (0, 28)), ("button2", (0, 58)), ("cap", (0, -76))):
        x, y = B(ex, ey)
        inner[nm] = [round(x, 1), round(y, 1)]
    return "\n".join(o) + "\n", feats, inner

def main():
    keys, marks = [], []
    for i in range(N):
        text, feats, inner = svg(i)
        name = "k%02d" % i
        with open(os.path.join(HERE, name + ".svg"), "w") as f:
            f.write(text)
        keys.append({"name": name, "drawing": name + ".png", "features": feats, "interior_features": inner})
    dt = 0.1
    for i in range(N):
        m = {"time": round(i * dt, 3), "key": "k%02d" % i}
        j = i % 8
        if j == 3:
            m["ease"] = "ease-out"          # the lifted foot slows into the top of its lift
        elif j == 4:
            m["ease"] = "ease-in"           # ... hangs there, then drops
        elif j == 0:
            m["ease"] = {"cubic_bezier": [0.2, 0.6, 0.4, 1]}   # lands fast, settles
        else:
            m["ease"] = "linear"
        marks.append(m)
    marks.append({"time": round(N * dt, 3), "key": "k00"})
    scene = {"version": 1, "reference": "k00", "edge_length": 15, "keys": keys,
             "timeline": {"fps": 24, "loop": True, "marks": marks}}
    with open(os.path.join(HERE, "scene.json"), "w") as f:
        f.write(json.dumps(scene, indent=1) + "\n")

main()
