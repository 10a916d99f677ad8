#!/usr/bin/env python3
"""Counts the triangles of OBJ, STL (ASCII and binary), PLY (ASCII and binary) and OFF files
independently of assimp and of fabform: the second reader tests/io/mesh_corpus_test.cpp's
counts are checked against (the counts are written into README.md).

A polygon of n >= 3 corners gives n - 2 triangles. A file prints one line:

    FILE: N triangles                          every element was usable
    FILE: N triangles; dropped: WHAT           N from the usable faces; WHAT was not usable
    FILE: error: WHY                           nothing can be read from the file

Standard library only:  /usr/bin/python3 count_triangles.py FILE_OR_FOLDER...
"""
import math
import os
import re
import struct
import sys


class MeshFileError(Exception):
    """The file cannot be read at all."""


class Count:
    """Triangles from usable faces, and a note for each kind of face that was not usable."""

    def __init__(self):
        self.triangles = 0
        self.dropped = {}

    def drop(self, why):
        self.dropped[why] = self.dropped.get(why, 0) + 1

    def polygon(self, corners, vertex_count):
        """Counts a polygon given as 0-based indices into vertex_count vertices."""
        if len(corners) < 3:
            self.drop('face with fewer than 3 vertices')
        elif any(i < 0 or i >= vertex_count for i in corners):
            self.drop('face indexing a missing vertex')
        else:
            self.triangles += len(corners) - 2

    def line(self):
        if not self.dropped:
            return '%d triangles' % self.triangles
        notes = ', '.join('%d %s' % (n, why) for why, n in sorted(self.dropped.items()))
        return '%d triangles; dropped: %s' % (self.triangles, notes)


def finite_number(word):
    """A coordinate: a decimal number that is finite (no 'nan', 'inf', '3.1+e2')."""
    if not re.fullmatch(r'[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?', word):
        raise MeshFileError('not a finite number: %r' % word)
    return float(word)


def text_of(data):
    """The bytes of a text format as text; a UTF-8 byte order mark is skipped."""
    if data.startswith(b'\xff\xfe') or data.startswith(b'\xfe\xff'):
        raise MeshFileError('UTF-16 text (byte order mark)')
    if b'\0' in data:
        raise MeshFileError('a NUL byte at offset %d: not ASCII or UTF-8 text' % data.index(b'\0'))
    if data.startswith(b'\xef\xbb\xbf'):
        data = data[3:]
    return data.decode('latin-1')


# --- OBJ ------------------------------------------------------------------------------------

def obj_lines(text):
    """Lines with comments removed and backslash continuations joined."""
    lines, pending = [], ''
    for raw in text.splitlines():
        line = raw.split('#', 1)[0]
        if line.rstrip().endswith('\\'):
            pending += line.rstrip()[:-1] + ' '
            continue
        lines.append(pending + line)
        pending = ''
    lines.append(pending)
    return [l.split() for l in lines if l.strip()]


def obj_index(word, vertices_so_far):
    """The 0-based vertex of a face corner 'v', 'v/t', 'v//n' or 'v/t/n'; None when invalid.
    A negative index counts back from the last vertex defined so far; 0 is never valid."""
    try:
        i = int(word.split('/')[0])
    except ValueError:
        return None
    if i == 0:
        return None
    return vertices_so_far + i if i < 0 else i - 1


def count_obj(data):
    records = obj_lines(text_of(data))
    total_vertices = sum(1 for r in records if r[0] == 'v')
    count, vertices = Count(), 0
    for r in records:
        if r[0] == 'v':
            vertices += 1
            used_coordinates = r[1:4]
            if len(used_coordinates) < 3:
                raise MeshFileError('vertex %d has fewer than 3 coordinates' % vertices)
            for word in used_coordinates:
                try:
                    finite_number(word)
                except MeshFileError:
                    count.drop('vertex with a malformed coordinate')
        elif r[0] == 'f':
            corners = [obj_index(w, vertices) for w in r[1:]]
            if any(c is None for c in corners):
                count.drop('face with index 0 or a non-number')
            else:
                count.polygon(corners, total_vertices)
    return count


# --- STL ------------------------------------------------------------------------------------

def ascii_stl_facets(text):
    """Facets of an ASCII STL ('solid ... endsolid', several solids allowed)."""
    words = text.split()
    facets, i = 0, 0
    while i < len(words):
        if words[i] != 'facet':
            i += 1
            continue
        end = words.index('endfacet', i) if 'endfacet' in words[i:] else -1
        if end < 0:
            raise MeshFileError('facet %d has no endfacet' % (facets + 1))
        body = words[i:end]
        corners = [j for j, w in enumerate(body) if w == 'vertex']
        if len(corners) != 3:
            raise MeshFileError('facet %d has %d vertices' % (facets + 1, len(corners)))
        for j in corners:
            for w in body[j + 1:j + 4]:
                finite_number(w)
        facets += 1
        i = end + 1
    return facets


def count_stl(data):
    # Binary when the size is exactly header + count records; otherwise ASCII, which is text
    # and starts with 'solid' (numpy-stl and trimesh decide the same way).
    if len(data) >= 84:
        (n,) = struct.unpack_from('<I', data, 80)
        if len(data) == 84 + 50 * n:
            for t in range(n):
                corners = struct.unpack_from('<9f', data, 84 + 50 * t + 12)
                if not all(math.isfinite(x) for x in corners):
                    raise MeshFileError('triangle %d has a coordinate that is not finite' % t)
            count = Count()
            count.triangles = n
            return count
    is_text = b'\0' not in data and not data.startswith((b'\xff\xfe', b'\xfe\xff'))
    if not is_text or not data.lstrip().startswith(b'solid'):
        if len(data) >= 84:
            (n,) = struct.unpack_from('<I', data, 80)
            raise MeshFileError('not ASCII; binary STL declares %d triangles (%d bytes) in %d bytes'
                                % (n, 84 + 50 * n, len(data)))
        raise MeshFileError('neither ASCII (no "solid") nor binary (shorter than 84 bytes)')
    count = Count()
    count.triangles = ascii_stl_facets(text_of(data))
    return count


# --- PLY ------------------------------------------------------------------------------------

SCALARS = {'char': 'b', 'int8': 'b', 'uchar': 'B', 'uint8': 'B', 'short': 'h', 'int16': 'h',
           'ushort': 'H', 'uint16': 'H', 'int': 'i', 'int32': 'i', 'uint': 'I', 'uint32': 'I',
           'float': 'f', 'float32': 'f', 'double': 'd', 'float64': 'd'}


def ply_header(data):
    """(format, [(element, count, [(name, type or (count type, item type))])], body offset)."""
    end = re.search(rb'end_header[ \t]*\r?\n', data)
    if not data.startswith(b'ply') or not end:
        raise MeshFileError('no "ply" ... "end_header" header')
    fmt, elements = None, []
    for line in data[:end.start()].decode('latin-1').splitlines()[1:]:
        w = line.split()
        if not w or w[0] in ('comment', 'obj_info'):
            continue
        if w[0] == 'format' and len(w) == 3:
            fmt = w[1]
        elif w[0] == 'element' and len(w) == 3 and w[2].isdigit():
            elements.append((w[1], int(w[2]), []))
        elif w[0] == 'property' and elements and len(w) == 5 and w[1] == 'list' \
                and w[2] in SCALARS and w[3] in SCALARS:
            elements[-1][2].append((w[4], (w[2], w[3])))
        elif w[0] == 'property' and elements and len(w) == 3 and w[1] in SCALARS:
            elements[-1][2].append((w[2], w[1]))
        else:
            raise MeshFileError('bad header line %r' % line)
    if fmt not in ('ascii', 'binary_little_endian', 'binary_big_endian'):
        raise MeshFileError('unknown format %r' % fmt)
    return fmt, elements, end.end()


class PlyBody:
    """Reads values one at a time from an ASCII or binary PLY body."""

    def __init__(self, fmt, body):
        self.fmt, self.body, self.at = fmt, body, 0
        if fmt == 'ascii':
            self.words = body.decode('latin-1').split()
        self.order = '>' if fmt == 'binary_big_endian' else '<'

    def value(self, type_):
        if self.fmt == 'ascii':
            if self.at >= len(self.words):
                raise MeshFileError('the data ends before the declared elements do')
            self.at += 1
            word = self.words[self.at - 1]
            return finite_number(word) if SCALARS[type_] in 'fd' else int(word)
        code = self.order + SCALARS[type_]
        if self.at + struct.calcsize(code) > len(self.body):
            raise MeshFileError('the data ends before the declared elements do')
        (v,) = struct.unpack_from(code, self.body, self.at)
        self.at += struct.calcsize(code)
        if SCALARS[type_] in 'fd' and not math.isfinite(v):
            raise MeshFileError('a coordinate is not finite')
        return v


def count_ply(data):
    fmt, elements, offset = ply_header(data)
    body = PlyBody(fmt, data[offset:])
    count, vertex_count = Count(), 0
    for name, n, properties in elements:
        vertex_count = n if name == 'vertex' else vertex_count
        for _ in range(n):
            for prop, type_ in properties:
                if isinstance(type_, tuple):
                    corners = [body.value(type_[1]) for _ in range(body.value(type_[0]))]
                    if name == 'face' and prop in ('vertex_indices', 'vertex_index'):
                        count.polygon(corners, vertex_count)
                else:
                    body.value(type_)
    return count


# --- OFF ------------------------------------------------------------------------------------

def off_records(data):
    """Non-blank lines as words, comments removed; only LF ends a line (CR is whitespace)."""
    records = []
    for line in text_of(data).split('\n'):
        words = line.split('#', 1)[0].split()
        if words:
            records.append(words)
    return records


def count_off(data):
    records = off_records(data)
    # The keyword may have its counts glued on ("OFF8 6 12", trimesh's whitespace.off).
    if not records or not records[0][0].startswith('OFF'):
        raise MeshFileError('no "OFF" keyword')
    head = records[0][1:] if records[0][0] == 'OFF' else [records[0][0][3:]] + records[0][1:]
    if not head:
        head, records = records[1], records[1:]
    try:
        vertices, faces = int(head[0]), int(head[1])  # the edge count is optional
    except (IndexError, ValueError):
        raise MeshFileError('no vertex and face counts')
    if len(records) < 1 + vertices + faces:
        raise MeshFileError('declares %d vertices and %d faces in %d lines'
                            % (vertices, faces, len(records) - 1))
    for words in records[1:1 + vertices]:
        if len(words) < 3:
            raise MeshFileError('a vertex line has fewer than 3 coordinates')
        for w in words[:3]:
            finite_number(w)
    count = Count()
    for words in records[1 + vertices:1 + vertices + faces]:
        n = int(words[0])
        if len(words) < 1 + n:
            raise MeshFileError('a face line declares %d vertices and holds %d' % (n, len(words) - 1))
        count.polygon([int(w) for w in words[1:1 + n]], vertices)  # any words after: a colour
    return count


READERS = {'.obj': count_obj, '.stl': count_stl, '.ply': count_ply, '.off': count_off}


def describe(path):
    with open(path, 'rb') as f:
        data = f.read()
    if not data.strip():
        return 'error: empty file' if not data else 'error: only white space'
    reader = READERS.get(os.path.splitext(path)[1].lower())
    if reader is None:
        return 'error: unknown extension'
    try:
        return reader(data).line()
    except MeshFileError as e:
        return 'error: %s' % e
    except ValueError as e:  # an index or count that is not an integer
        return 'error: %s' % e


def main(paths):
    """Counts each file named; a folder stands for its mesh files (by extension), sorted."""
    for path in paths:
        if os.path.isdir(path):
            names = sorted(n for n in os.listdir(path) if os.path.splitext(n)[1].lower() in READERS)
            main([os.path.join(path, n) for n in names])
        else:
            print('%s: %s' % (os.path.basename(path), describe(path)))


if __name__ == '__main__':
    main(sys.argv[1:])
