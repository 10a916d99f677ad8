#!/usr/bin/env python3
"""Writes the handmade_* files of this folder: small meshes, written by us, for the kinds of bad
input the mesh corpus test needs and the upstream files do not have (README.md lists each with
its expected outcome). Each is a unit cube (8 vertices, 12 triangles, outward) in some format,
spoilt in one way, or one the reader must mend. Deterministic: running it again rewrites the
same bytes.

Standard library only:  /usr/bin/python3 make_handmade.py   (writes next to itself)
"""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

# The unit cube: vertices 0..7 at the corners (x, y, z in {0, 1}), 12 triangles facing out.
CUBE_V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_T = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
          (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]


def write(name, data):
    if isinstance(data, str):
        data = data.encode('ascii')
    with open(os.path.join(HERE, name), 'wb') as f:
        f.write(data)


def obj(vertices=CUBE_V, triangles=CUBE_T, extra=''):
    lines = ['# unit cube, written for fabform\'s mesh corpus test']
    lines += ['v %s %s %s' % v for v in vertices]
    lines += ['f %d %d %d' % (a + 1, b + 1, c + 1) for a, b, c in triangles]
    return '\n'.join(lines) + '\n' + extra


def ascii_stl(vertices=CUBE_V, triangles=CUBE_T):
    out = ['solid cube']
    for t in triangles:
        out += ['  facet normal 0 0 0', '    outer loop']
        out += ['      vertex %s %s %s' % vertices[i] for i in t]
        out += ['    endloop', '  endfacet']
    return '\n'.join(out + ['endsolid cube']) + '\n'


def binary_stl(header, vertices=CUBE_V, triangles=CUBE_T, count=None):
    data = header.ljust(80, b' ')[:80]
    data += struct.pack('<I', len(triangles) if count is None else count)
    for t in triangles:
        data += struct.pack('<3f', 0, 0, 0)
        for i in t:
            data += struct.pack('<3f', *vertices[i])
        data += b'\0\0'
    return data


def ascii_ply(vertices=CUBE_V, faces=CUBE_T, vertex_count=None):
    head = ['ply', 'format ascii 1.0', 'comment unit cube, written for fabform\'s mesh corpus test',
            'element vertex %d' % (len(vertices) if vertex_count is None else vertex_count),
            'property float x', 'property float y', 'property float z',
            'element face %d' % len(faces), 'property list uchar int vertex_indices', 'end_header']
    body = ['%s %s %s' % v for v in vertices]
    body += [' '.join(str(x) for x in (len(f),) + tuple(f)) for f in faces]
    return '\n'.join(head + body) + '\n'


def binary_ply(vertices=CUBE_V, faces=CUBE_T, first_element=''):
    head = ('ply\nformat binary_little_endian 1.0\n' + first_element +
            'element vertex %d\nproperty float x\nproperty float y\nproperty float z\n'
            'element face %d\nproperty list uchar int vertex_indices\nend_header\n'
            % (len(vertices), len(faces)))
    body = b''.join(struct.pack('<3f', *v) for v in vertices)
    body += b''.join(struct.pack('<B%di' % len(f), len(f), *f) for f in faces)
    return head.encode('ascii'), body


def off(vertices=CUBE_V, faces=CUBE_T):
    lines = ['OFF', '%d %d 0' % (len(vertices), len(faces))]
    lines += ['%s %s %s' % v for v in vertices]
    lines += [' '.join(str(x) for x in (len(f),) + tuple(f)) for f in faces]
    return '\n'.join(lines) + '\n'


def main():
    inf, nan = float('inf'), float('nan')

    # Good files the reader must mend before assimp 5.2.5 reads them right.
    write('handmade_utf8_bom.obj', b'\xef\xbb\xbf' + obj().encode('ascii'))
    head, body = binary_ply(first_element='element material 1\nproperty uchar red\n')
    write('handmade_ply_element_before_vertices.ply', head + b'\x07' + body)

    # Usable, with something dropped (a warning says what).
    write('handmade_two_corner_face.off', off(faces=CUBE_T + [(0, 6)]))
    write('handmade_face_without_corners.ply', ascii_ply(faces=CUBE_T + [()]))

    # Truncated.
    write('handmade_truncated_binary.stl', binary_stl(b'binary STL, cut short')[:84 + 50 * 5 + 25])
    write('handmade_truncated_binary_solid_header.stl',
          binary_stl(b'solid cube exported as binary, cut short')[:84 + 50 * 5 + 25])
    text = ascii_stl()
    write('handmade_truncated_ascii.stl', text[:text.index('vertex', text.index('facet', 600))])
    head, body = binary_ply()
    write('handmade_truncated_binary.ply', head + body[:-7])  # in the last face's corner list

    # Declared counts larger than the data.
    write('handmade_huge_count_binary.stl', binary_stl(b'binary STL', triangles=CUBE_T[:1], count=0xFFFFFFFF))
    write('handmade_huge_count.ply', ascii_ply(vertex_count=4000000000))
    write('handmade_huge_count.off', 'OFF\n2000000000 12 0\n0 0 0\n1 0 0\n')

    # NaN and infinite coordinates.
    write('handmade_nan_vertex.obj', obj().replace('v 1 1 1', 'v nan 1 1'))
    write('handmade_inf_vertex_ascii.stl', ascii_stl().replace('vertex 1 1 1', 'vertex 1 inf 1', 1))
    vertices = list(CUBE_V)
    vertices[6] = (1, 1, nan)
    write('handmade_nan_vertex_binary.stl', binary_stl(b'binary STL with a NaN', vertices=vertices))
    vertices[6] = (inf, 1, 1)
    head, body = binary_ply(vertices=vertices)
    write('handmade_inf_vertex_binary.ply', head + body)

    # Indices out of range.
    write('handmade_index_out_of_range.ply', ascii_ply(faces=CUBE_T[:-1] + [(3, 4, 8)]))
    write('handmade_index_out_of_range.off', off(faces=CUBE_T[:-1] + [(3, 4, 9)]))

    # UTF-16 text, with and without a byte order mark, and empty files.
    write('handmade_utf16le_bom.obj', obj().encode('utf-16'))  # Python writes the BOM, little endian
    write('handmade_utf16le_no_bom.obj', obj().encode('utf-16-le'))
    write('handmade_utf16be_bom.stl', b'\xfe\xff' + ascii_stl().encode('utf-16-be'))
    write('handmade_empty.stl', b'')
    write('handmade_blank_lines.obj', '\n\n   \n\t\n')


if __name__ == '__main__':
    main()
