# Reads the cut points and features of the glyph scenes (tests/topology/glyph-*/) off their drawings
# (draw_glyphs.mjs) and writes each scene.json: `python3 tests/topology/glyph_features.py`. A pixel
# is the shape's where its alpha is at least half; positions are pixel edges (drawing px).
import json, os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))

def read_png(path):  # 8-bit RGBA, non-interlaced -> (width, height, alpha rows)
    data = open(path, 'rb').read()
    assert data[:8] == b'\x89PNG\r\n\x1a\n'
    pos, idat = 8, b''
    while pos < len(data):
        length, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b'IHDR':
            w, h, depth, colour = struct.unpack('>IIBB', body[:10])
            assert depth == 8 and colour == 6, path
        elif kind == b'IDAT':
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), 4 * w, [], bytearray(4 * w)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 4] if i >= 4 else 0
            b, c = prev[i], prev[i - 4] if i >= 4 else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([line[4 * x + 3] >= 128 for x in range(w)])
        prev = line
    return rows

def runs(row):  # [start, end) of the shape's pixels along a row
    out, x = [], 0
    while x < len(row):
        if row[x]:
            s = x
            while x < len(row) and row[x]: x += 1
            out.append((s, x))
        else:
            x += 1
    return out

def column(rows, x):
    return [rows[y][x] for y in range(len(rows))]

def bbox(rows):
    ys = [y for y, r in enumerate(rows) if any(r)]
    xs = [x for x in range(len(rows[0])) if any(r[x] for r in rows)]
    return xs[0], ys[0], xs[-1] + 1, ys[-1] + 1

def scene(folder, keys):
    text = json.dumps({'version': 1, 'keys': keys, 'timeline': {'fps': 24, 'loop': True, 'marks': [
        {'time': 0, 'key': keys[0]['name'], 'ease': 'ease-in-out'}, {'time': 1, 'key': keys[1]['name'], 'ease': 'ease-in-out'},
        {'time': 2, 'key': keys[0]['name']}]}}, indent=1)
    open(os.path.join(HERE, folder, 'scene.json'), 'w').write(text + '\n')
    print('wrote', folder + '/scene.json')

# l -> i: a split across the l where the i's dot parts from its stem.
l, i = read_png(os.path.join(HERE, 'glyph-l-i', 'l.png')), read_png(os.path.join(HERE, 'glyph-l-i', 'i.png'))
il, it, ir, ib = bbox(i)
mid = (il + ir) // 2
col = column(i, mid)
dot_bottom = next(y for y in range(it, ib) if not col[y])
stem_top = next(y for y in range(dot_bottom, ib) if col[y])
gap = (dot_bottom + stem_top) // 2
(ll, lr), = runs(l[gap])
lx0, lt, lx1, lb = bbox(l)
scene('glyph-l-i', [
    {'name': 'l', 'drawing': 'l.png', 'features': {'top': [(lx0 + lx1) / 2, lt], 'bottom': [(lx0 + lx1) / 2, lb]},
     'cuts': [{'name': 'dot', 'kind': 'split', 'points': [[ll, gap + 0.5], [lr, gap + 0.5]]}]},
    {'name': 'i', 'drawing': 'i.png', 'features': {
        'top': [mid + 0.5, it], 'bottom': [mid + 0.5, ib],
        'dot.start.left': [il, dot_bottom], 'dot.start.right': [il, stem_top],
        'dot.end.left': [ir, dot_bottom], 'dot.end.right': [ir, stem_top]}}])

# O -> C: a split from the O's hole to its outline on the right, where the C's terminals part.
o, c = read_png(os.path.join(HERE, 'glyph-o-c', 'o.png')), read_png(os.path.join(HERE, 'glyph-o-c', 'c.png'))
ox0, oy0, ox1, oy1 = bbox(o)
oy = (oy0 + oy1) // 2
(_, _), (hole_right, outer_right) = runs(o[oy])
cx0, cy0, cx1, cy1 = bbox(c)
cy = (cy0 + cy1) // 2
def terminal(upper):  # the vertical end of a C's terminal: its x and its run there
    ys = range(cy0, cy) if upper else range(cy, cy1)
    x_end = max(x for y in ys for (s, e) in runs(c[y]) if s > (cx0 + cx1) // 2 for x in [e])
    col = column(c, x_end - 2)
    run = [y for y in ys if col[y]]
    return x_end, run[0], run[-1] + 1
ux, ut, ub = terminal(True)
lx, lt2, lb2 = terminal(False)
scene('glyph-o-c', [
    {'name': 'o', 'drawing': 'o.png', 'features': {'left': [ox0, oy + 0.5]},
     'cuts': [{'name': 'gap', 'kind': 'split', 'points': [[hole_right, oy + 0.5], [outer_right, oy + 0.5]]}]},
    {'name': 'c', 'drawing': 'c.png', 'features': {
        'left': [cx0, cy + 0.5],
        'gap.start.left': [ux, ub], 'gap.start.right': [lx, lt2],
        'gap.end.left': [ux, ut], 'gap.end.right': [lx, lb2]}}])
