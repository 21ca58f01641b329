# Draws the correspondence test scenes (tests/correspondence/*/): drawings where part of the artwork
# is the same in every key and part moves, inked, filled, with interior detail, at the sizes
# artists use. Pure Python: `python3 tests/correspondence/draw.py` rewrites every PNG here.
#   cat-tail      512 px, 3 keys: head and body the same pixels in every key, the tail swings.
#   chick-squash   96 px, 3 keys: a chick stands, squashes, stretches; its stripe, eye and beak move with it.
#   lean-mirror   256 px, 2 keys: a blob with a face leaning left, and its mirror image.
import math, os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))
INK = (40, 30, 60)

def png(path, size, colour, samples=3):  # colour(x, y) -> (r, g, b) or None; samples x samples per pixel
    rows = bytearray()
    for y in range(size):
        rows += b'\0'
        for x in range(size):
            acc, n = [0, 0, 0], 0
            for j in range(samples):
                for i in range(samples):
                    c = colour(x + (i + .5) / samples, y + (j + .5) / samples)
                    if c:
                        n += 1
                        for k in range(3): acc[k] += c[k]
            rows += bytes((acc[0] // n, acc[1] // n, acc[2] // n, 255 * n // samples ** 2) if n else (0, 0, 0, 0))
    chunk = lambda t, d: struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d))
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', size, size, 8, 6, 0, 0, 0))
                + chunk(b'IDAT', zlib.compress(bytes(rows), 9)) + chunk(b'IEND', b''))

# Signed distances (negative inside), px.
def circle(cx, cy, r): return lambda x, y: math.hypot(x - cx, y - cy) - r
def ellipse(cx, cy, rx, ry):  # an approximate distance, exact enough for drawing
    return lambda x, y: (math.hypot((x - cx) / rx, (y - cy) / ry) - 1) * min(rx, ry)
def union(*fs): return lambda x, y: min(f(x, y) for f in fs)
def minus(a, b): return lambda x, y: max(a(x, y), -b(x, y))
def smooth_union(a, b, k):
    def d(x, y):
        da, db = a(x, y), b(x, y)
        h = max(k - abs(da - db), 0) / k
        return min(da, db) - h * h * k / 4
    return d
def band(y0, y1): return lambda x, y: max(y0 - y, y - y1)  # between two rows
def triangle(a, b, c):  # inside where all three edges agree (distance to the nearest edge line)
    if (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) < 0: b, c = c, b  # either winding
    def d(x, y):
        out = -1e9
        for (px, py), (qx, qy) in ((a, b), (b, c), (c, a)):
            ex, ey = qx - px, qy - py
            out = max(out, ((x - px) * ey - (y - py) * ex) / math.hypot(ex, ey))
        return out
    return d
def capsule_path(points, r0, r1):  # a stroke along a polyline, its radius r0 -> r1 from start to end
    segments = list(zip(points, points[1:]))
    total = sum(math.dist(p, q) for p, q in segments)
    def d(x, y):
        best, walked = 1e9, 0
        for (px, py), (qx, qy) in segments:
            ex, ey = qx - px, qy - py
            length2 = ex * ex + ey * ey
            t = min(max(((x - px) * ex + (y - py) * ey) / length2, 0), 1)
            r = r0 + (r1 - r0) * (walked + t * math.sqrt(length2)) / total
            best = min(best, math.hypot(x - px - t * ex, y - py - t * ey) - r)
            walked += math.sqrt(length2)
        return best
    return d
def bezier(p0, p1, p2, n=24):
    return [((1 - t) ** 2 * p0[0] + 2 * (1 - t) * t * p1[0] + t * t * p2[0],
             (1 - t) ** 2 * p0[1] + 2 * (1 - t) * t * p1[1] + t * t * p2[1]) for t in (i / n for i in range(n + 1))]
def bounded(f, box, margin=4):  # f far from its bounding box is just "far": skips the work there
    x0, y0, x1, y1 = box
    return lambda x, y: f(x, y) if x0 - margin <= x <= x1 + margin and y0 - margin <= y <= y1 + margin else 99

def inked(shape, fill, details=(), ink=3):  # details: (distance, colour), later ones over earlier
    def colour(x, y):
        d = shape(x, y)
        if d > 0: return None
        if d > -ink: return INK
        c = fill
        for detail, dc in details:
            if detail(x, y) < 0: c = dc
        return c
    return colour

ORANGE, CREAM, BROWN, PINK, GREEN = (235, 150, 60), (250, 235, 210), (150, 80, 40), (240, 150, 170), (80, 170, 90)
YELLOW, RED, BLUE = (250, 205, 50), (215, 60, 50), (70, 120, 200)

# cat-tail: a sitting cat; head, ears, body, paws the same in every key; the tail down, out, up.
head = union(circle(200, 170, 70), triangle((138, 135), (150, 70), (190, 108)), triangle((262, 135), (250, 70), (210, 108)))
body = smooth_union(ellipse(230, 320, 105, 120), head, 20)  # the torso, below
paws = union(ellipse(180, 440, 34, 20), ellipse(275, 440, 34, 20))
cat = union(body, paws)
torso = ellipse(230, 320, 105, 120)
stripe = lambda y0, y1: (lambda x, y: max(band(y0, y1)(x, y), torso(x, y)))  # across the body only
cat_details = [(stripe(250, 262), BROWN), (stripe(300, 312), BROWN), (stripe(350, 362), BROWN),
               (ellipse(200, 330, 45, 70), CREAM), (ellipse(200, 205, 30, 18), CREAM),
               (circle(175, 160, 9), INK), (circle(225, 160, 9), INK), (triangle((192, 185), (208, 185), (200, 195)), PINK)]
tails = {'down': bezier((320, 360), (420, 420), (440, 470)),
         'out': bezier((320, 360), (420, 330), (480, 300)),
         'up': bezier((320, 360), (420, 300), (400, 170))}
for name, points in tails.items():
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    tail = bounded(capsule_path(points, 22, 12), (min(xs) - 22, min(ys) - 22, max(xs) + 22, max(ys) + 22))
    tip = bounded(capsule_path(points[-5:], 13, 12), (min(xs) - 22, min(ys) - 22, max(xs) + 22, max(ys) + 22))
    png(os.path.join(HERE, 'cat-tail', name + '.png'), 512,
        inked(union(cat, tail), ORANGE, cat_details[:3] + [(tip, BROWN)] + cat_details[3:]), samples=2)

# chick-squash: a round chick that squashes and stretches (area kept), its stripe, eye, beak and
# feet moving with it.
def chick(rx, ry):
    cx, cy = 48, 87 - ry
    feet = union(ellipse(cx - 7, 88, 7, 3.5), ellipse(cx + 7, 88, 7, 3.5))  # overlapping the body at any squash
    beak = triangle((cx + rx - 4, cy - 0.30 * ry), (cx + rx + 9, cy - 0.18 * ry), (cx + rx - 4, cy - 0.06 * ry))
    shape = union(ellipse(cx, cy, rx, ry), feet, beak)
    details = [(band(cy + 0.10 * ry, cy + 0.30 * ry), RED), (beak, (240, 140, 30)),
               (circle(cx + 0.45 * rx, cy - 0.35 * ry, 3), INK), (feet, (240, 140, 30))]
    return inked(shape, YELLOW, details, ink=2)
for name, (rx, ry) in {'stand': (26, 30), 'squash': (34, 23), 'stretch': (21, 37)}.items():
    png(os.path.join(HERE, 'chick-squash', name + '.png'), 96, chick(rx, ry), samples=4)

# lean-mirror: a blob with a face, leaning left, and the same drawing mirrored.
def lean(sign):
    m = lambda f: (lambda x, y: f(256 - x if sign > 0 else x, y))
    blob = m(smooth_union(ellipse(128, 170, 70, 60), circle(98, 95, 45), 40))
    face = [(m(band(150, 162)), BLUE), (m(circle(86, 90, 8)), INK), (m(circle(116, 92, 8)), INK)]
    return inked(blob, GREEN, face)
png(os.path.join(HERE, 'lean-mirror', 'left.png'), 256, lean(-1))
png(os.path.join(HERE, 'lean-mirror', 'right.png'), 256, lean(+1))
