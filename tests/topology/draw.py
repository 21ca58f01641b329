# Draws the drawings of the topology-change scenes (tests/topology/*/): shapes that open, split and
# merge, inked (a dark outline 3 px wide), filled, with interior detail. Pure Python, like the
# README's chomp: `python3 tests/topology/draw.py` rewrites every PNG here.
import math, os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))
SIZE = 256
INK = (40, 30, 60)

def png(path, colour):  # colour(x, y) -> (r, g, b, a) or None; 4 x 4 samples per pixel
    rows = bytearray()
    for y in range(SIZE):
        rows += b'\0'
        for x in range(SIZE):
            acc, n = [0, 0, 0], 0
            for j in range(4):
                for i in range(4):
                    c = colour(x + (i + .5) / 4, y + (j + .5) / 4)
                    if c:
                        n += 1
                        for k in range(3): acc[k] += c[k]
            rows += bytes((acc[0] // n, acc[1] // n, acc[2] // n, 255 * n // 16) if n else (0, 0, 0, 0))
    chunk = lambda t, d: struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t + d))
    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', SIZE, SIZE, 8, 6, 0, 0, 0))
                + chunk(b'IDAT', zlib.compress(bytes(rows))) + chunk(b'IEND', b''))

# Signed distances (negative inside), px.
circle = lambda cx, cy, r: lambda x, y: math.hypot(x - cx, y - cy) - r
def smooth_union(a, b, k):
    def d(x, y):
        da, db = a(x, y), b(x, y)
        h = max(k - abs(da - db), 0) / k
        return min(da, db) - h * h * k / 4
    return d
union = lambda *fs: lambda x, y: min(f(x, y) for f in fs)
minus = lambda a, b: lambda x, y: max(a(x, y), -b(x, y))

def inked(shape, fill, details=()):  # details: (distance, colour) drawn over the fill
    def colour(x, y):
        d = shape(x, y)
        if d > 0: return None
        if d > -3: return INK
        for detail, c in details:
            if detail(x, y) < 0: return c
        return fill
    return colour

def write(scene, name, colour):
    os.makedirs(os.path.join(HERE, scene), exist_ok=True)
    png(os.path.join(HERE, scene, name), colour)

BLUE, YELLOW, RED, PINK = (90, 160, 230), (250, 200, 40), (220, 70, 60), (240, 150, 170)

# drop-split: a drop with a face hangs, necks, and splits in two (a `split` across the neck).
eyes = lambda cy: [(circle(112, cy, 6), INK), (circle(144, cy, 6), INK), (circle(128, cy + 18, 4), PINK)]
write('drop-split', 'hang.png', inked(smooth_union(circle(128, 105, 52), circle(128, 180, 60), 60), BLUE, eyes(185)))
write('drop-split', 'neck.png', inked(smooth_union(circle(128, 88, 46), circle(128, 188, 56), 14), BLUE, eyes(191)))
write('drop-split', 'split.png', inked(union(circle(128, 72, 42), circle(128, 196, 52)), BLUE, eyes(199)))

# chomp: the README's disc opening its mouth (a `notch`), inked, with an eye.
disc = circle(128, 128, 100)
def wedge(x, y):  # the mouth: within 35 degrees of the +x axis from the centre (signed distance)
    r, t = math.hypot(x - 128, y - 128), abs(math.atan2(y - 128, x - 128)) - math.radians(35)
    return r * math.sin(t) if t < math.pi / 2 else r
eye = [(circle(140, 70, 9), INK)]
write('chomp', 'closed.png', inked(disc, YELLOW, eye))
write('chomp', 'open.png', inked(minus(disc, wedge), YELLOW, eye))

# ring-open: a ring (O) opens into a C (a `split` from the hole to the outline, on the right).
ring = minus(circle(128, 128, 90), circle(128, 128, 50))
gap = lambda x, y: max(abs(y - 128) - 22, 128 - x)  # a bar from the centre out to the right
write('ring-open', 'o.png', inked(ring, RED))
write('ring-open', 'c.png', inked(minus(ring, gap), RED))

# blobs-merge: two blobs apart, then one (a `split` where they join, in the merged key).
write('blobs-merge', 'apart.png', inked(union(circle(78, 128, 48), circle(182, 128, 48)), YELLOW,
                                        [(circle(78, 118, 8), INK), (circle(182, 118, 8), INK)]))
write('blobs-merge', 'one.png', inked(smooth_union(circle(92, 128, 52), circle(168, 128, 52), 30), YELLOW,
                                      [(circle(92, 118, 8), INK), (circle(168, 118, 8), INK)]))
