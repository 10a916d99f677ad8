#!/usr/bin/env python3
"""Counts the triangles of a VRML97 file independently of Coin3D.

A small generic VRML97 parser (standard library only): tokens, nodes with DEF/USE, fields
whose values are nodes, lists or scalars.  The scene is then walked as a VRML97 browser
would: Group/Transform/Anchor/Collision/Billboard children, the chosen child of a Switch
(whichChoice, -1 = none), Shape geometry.  An IndexedFaceSet contributes n - 2 triangles for
each polygon of n >= 3 indices in coordIndex (polygons end at -1 or at the end of the list);
a USE of a node counts again.  Points are transformed by the Transform stack (VRML97 spec
4.6.5: T C R SR S -SR -C) to give a bounding box of the referenced points.  Other geometry
(Sphere, Box, Text, ...) is reported by name and not counted.  Distinct positions: the
referenced points, rounded to 32-bit floats as Coin stores them, distinct per transform.

    python3 count_triangles.py FILE...
"""
import math
import re
import struct
import sys

TOKEN = re.compile(r'"(?:[^"\\]|\\.)*"|[\[\]{}]|[^\s,\[\]{}"#]+')


def tokenize(text):
    out = []
    for line in text.splitlines():
        # strip comments (a '#' outside strings)
        pos = 0
        while pos < len(line):
            m = re.compile(r'\s*(,|\s)*').match(line, pos)
            pos = m.end()
            if pos >= len(line) or line[pos] == '#':
                break
            m = TOKEN.match(line, pos)
            if not m:
                raise ValueError('cannot tokenize: ' + line[pos:])
            out.append(m.group(0))
            pos = m.end()
    return out


class Node:
    def __init__(self, type_):
        self.type = type_
        self.fields = {}


class Parser:
    def __init__(self, tokens):
        self.t = tokens
        self.i = 0
        self.defs = {}

    def peek(self):
        return self.t[self.i] if self.i < len(self.t) else None

    def next(self):
        tok = self.t[self.i]
        self.i += 1
        return tok

    def is_node_start(self, tok):
        return tok in ('DEF', 'USE', 'NULL') or (tok[0].isupper() and tok not in ('TRUE', 'FALSE'))

    def node(self):
        tok = self.next()
        if tok == 'NULL':
            return None
        if tok == 'USE':
            return self.defs[self.next()]
        name = None
        if tok == 'DEF':
            name = self.next()
            tok = self.next()
        n = Node(tok)
        if name:
            self.defs[name] = n
        assert self.next() == '{', tok
        while self.peek() != '}':
            field = self.next()
            n.fields[field] = self.value()
        self.next()
        return n

    def value(self):
        tok = self.peek()
        if tok == '[':
            self.next()
            items = []
            while self.peek() != ']':
                items.append(self.node() if self.is_node_start(self.peek()) else self.scalar(self.next()))
            self.next()
            return items
        if self.is_node_start(tok):
            return self.node()
        vals = []
        while True:
            tok = self.peek()
            if tok is None or tok in ('}', ']', '[', '{'):
                break
            if tok in ('TRUE', 'FALSE') or tok.startswith('"') or re.match(r'^[-+.0-9]', tok):
                vals.append(self.scalar(self.next()))
            else:
                break
        return vals[0] if len(vals) == 1 else vals

    @staticmethod
    def scalar(tok):
        if tok == 'TRUE':
            return True
        if tok == 'FALSE':
            return False
        if tok.startswith('"'):
            return tok[1:-1]
        try:
            return int(tok, 0) if re.match(r'^[-+]?(0x[0-9a-fA-F]+|[0-9]+)$', tok) else float(tok)
        except ValueError:
            return tok

    def scene(self):
        nodes = []
        while self.peek() is not None:
            nodes.append(self.node())
        return nodes


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def translate(v):
    m = [[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]
    for i in range(3):
        m[i][3] = v[i]
    return m


def scale(v):
    return [[(v[i] if i < 3 else 1.0) if i == j else 0.0 for j in range(4)] for i in range(4)]


def rotate(r):
    x, y, z, a = r
    n = math.sqrt(x * x + y * y + z * z)
    if n == 0 or a == 0:
        return scale([1, 1, 1])
    x, y, z = x / n, y / n, z / n
    c, s, t = math.cos(a), math.sin(a), 1 - math.cos(a)
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0],
            [0, 0, 0, 1]]


def vec(v, default):
    return list(v) if isinstance(v, list) and v else default


def transform_matrix(n):
    f = n.fields
    t = vec(f.get('translation'), [0, 0, 0])
    c = vec(f.get('center'), [0, 0, 0])
    r = vec(f.get('rotation'), [0, 0, 1, 0])
    s = vec(f.get('scale'), [1, 1, 1])
    sr = vec(f.get('scaleOrientation'), [0, 0, 1, 0])
    m = translate(t)
    m = matmul(m, translate(c))
    m = matmul(m, rotate(r))
    m = matmul(m, rotate(sr))
    m = matmul(m, scale(s))
    m = matmul(m, rotate([sr[0], sr[1], sr[2], -sr[3]]))
    return matmul(m, translate([-c[0], -c[1], -c[2]]))


def children(n, key):
    v = n.fields.get(key)
    if v is None:
        return []
    return v if isinstance(v, list) else [v]


class Counter:
    def __init__(self):
        self.triangles = 0
        self.polygons = {}
        self.other = {}
        self.empty_shapes = 0
        self.ccw_false = 0
        self.lo = [math.inf] * 3
        self.hi = [-math.inf] * 3
        self.positions = set()

    def walk(self, n, m):
        if n is None or isinstance(n, (int, float, str, bool)):
            return
        t = n.type
        if t == 'Transform':
            m = matmul(m, transform_matrix(n))
        if t in ('Group', 'Transform', 'Anchor', 'Collision', 'Billboard'):
            for c in children(n, 'children'):
                self.walk(c, m)
        elif t == 'Switch':
            which = n.fields.get('whichChoice', -1)
            ch = children(n, 'choice')
            if isinstance(which, int) and 0 <= which < len(ch):
                self.walk(ch[which], m)
        elif t == 'Shape':
            g = n.fields.get('geometry')
            if g is None:
                self.empty_shapes += 1
            elif g.type == 'IndexedFaceSet':
                self.face_set(g, m)
            else:
                self.other[g.type] = self.other.get(g.type, 0) + 1

    def face_set(self, g, m):
        pts = g.fields['coord'].fields.get('point', [])
        pts = [pts[k:k + 3] for k in range(0, len(pts), 3)]
        idx = g.fields.get('coordIndex', [])
        idx = idx if isinstance(idx, list) else [idx]
        if g.fields.get('ccw') is False:
            self.ccw_false += 1
        poly = []
        for k in idx + [-1]:
            if k >= 0:
                poly.append(k)
                continue
            if len(poly) >= 3:
                self.triangles += len(poly) - 2
                self.polygons[len(poly)] = self.polygons.get(len(poly), 0) + 1
                for p in poly:
                    # Coin stores coordinates as 32-bit floats: count distinct points as floats,
                    # per transform (the same point under another transform is another position).
                    f32 = tuple(struct.unpack('f', struct.pack('f', v))[0] for v in pts[p])
                    self.positions.add((tuple(map(tuple, m)), f32))
                    x = [sum(m[i][j] * (pts[p] + [1])[j] for j in range(4)) for i in range(3)]
                    self.lo = [min(a, b) for a, b in zip(self.lo, x)]
                    self.hi = [max(a, b) for a, b in zip(self.hi, x)]
            poly = []


def main():
    for path in sys.argv[1:]:
        with open(path, encoding='utf-8', errors='replace') as f:
            text = f.read()
        c = Counter()
        for n in Parser(tokenize(text)).scene():
            c.walk(n, scale([1, 1, 1]))
        print(f'{path}: {c.triangles} triangles, {len(c.positions)} distinct positions; polygons by size {dict(sorted(c.polygons.items()))}; '
              f'other geometry {c.other}; shapes without geometry {c.empty_shapes}; ccw FALSE {c.ccw_false}; '
              f'bbox {["%.9g" % v for v in c.lo]} .. {["%.9g" % v for v in c.hi]}')


if __name__ == '__main__':
    main()
