#!/usr/bin/env python3
"""Writes the binary test files the way VTK and Gmsh lay them out (run from this directory).

Python's struct, zlib, lzma and base64 only: a second writer, independent of tetcut's, so that
reading these files tests the readers against the formats' specifications, not against our own
writers. Two tets A B C D / B C D E plus a triangle, in:
  - two_tets_*.vtu: inline base64 with a UInt32 header (one stream for header and data), inline
    base64 with a UInt64 header (header and data encoded as two streams, as VTK does for
    compressed data), appended raw, appended base64;
  - binary/vtu_<order>_<header>_<layout>_<compressor>.vtu: every combination of byte order
    (le, be), header type (u32, u64), layout (inline, raw, b64) and compressor (none, zlib,
    lzma); compressed arrays in blocks of 32 bytes, so that most span several blocks with a
    partial last one;
  - binary/*.vtk: legacy BINARY (big-endian) 3.0 with FIELD data and float points, 5.1 with
    OFFSETS/CONNECTIVITY, and POLYDATA surfaces (a tetrahedron's 4 faces as polygons, as strips);
  - binary/*.msh: Gmsh 2.2 and 4.1 binary in both byte orders (4.1 with a binary $Entities, a
    parametric node block and 4-byte size_t in one file);
  - binary/tetra_surface.vtp: XML PolyData.
"""
import base64
import lzma
import os
import struct
import zlib

POINTS = [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1]
CONN = [0, 1, 2, 3, 1, 2, 3, 1, 2, 3, 4]
OFFSETS = [4, 7, 11]
TYPES = [10, 5, 10]


def pack(fmt, values):
    return struct.pack('<%d%s' % (len(values), fmt), *values)


def arrays(real, integer):
    return [('Points', 'Float64' if real == 'd' else 'Float32', pack(real, POINTS), 3),
            ('connectivity', 'Int64' if integer == 'q' else 'Int32', pack(integer, CONN), 1),
            ('offsets', 'Int64' if integer == 'q' else 'Int32', pack(integer, OFFSETS), 1),
            ('types', 'UInt8', pack('B', TYPES), 1)]


def document(header_type, body_arrays, appended=b'', compressor=''):
    head = '<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian"'
    if header_type:
        head += ' header_type="%s"' % header_type
    if compressor:
        head += ' compressor="%s"' % compressor
    head += '>\n  <UnstructuredGrid>\n    <Piece NumberOfPoints="5" NumberOfCells="3">\n'
    points = body_arrays[0]
    cells = body_arrays[1:]
    out = head + '      <Points>\n' + points + '      </Points>\n      <Cells>\n' + ''.join(cells)
    out += '      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n'
    return out.encode() + appended + b'</VTKFile>\n'


def tag(name, vtype, ncomp, fmt, content=None, offset=None):
    attrs = 'type="%s" Name="%s" NumberOfComponents="%d" format="%s"' % (vtype, name, ncomp, fmt)
    if offset is not None:
        return '        <DataArray %s offset="%d"/>\n' % (attrs, offset)
    return '        <DataArray %s>\n          %s\n        </DataArray>\n' % (attrs, content)


def inline(header_fmt, real, integer, split_streams):
    out = []
    for name, vtype, data, ncomp in arrays(real, integer):
        header = struct.pack('<' + header_fmt, len(data))
        if split_streams:
            text = base64.b64encode(header).decode() + base64.b64encode(data).decode()
        else:
            text = base64.b64encode(header + data).decode()
        out.append(tag(name, vtype, ncomp, 'binary', text))
    return out


def appended(encoding):
    out = []
    blob = b''
    for name, vtype, data, ncomp in arrays('f', 'i'):
        chunk = struct.pack('<I', len(data)) + data
        if encoding == 'base64':
            chunk = base64.b64encode(chunk)
        out.append(tag(name, vtype, ncomp, 'appended', offset=len(blob)))
        blob += chunk
    return out, b'  <AppendedData encoding="%s">\n   _' % encoding.encode() + blob + b'\n  </AppendedData>\n'


# ---- the matrix of VTU encodings ---------------------------------------------------------------

BLOCK = 32


def vtu_block(data, order, header_fmt, compressor):
    """One array's bytes as VTK lays them out: header then data, compressed in blocks or not."""
    h = lambda *values: struct.pack(order + header_fmt * len(values), *values)
    if compressor == 'none':
        return h(len(data)), data
    compress = zlib.compress if compressor == 'zlib' else lambda b: lzma.compress(b, format=lzma.FORMAT_XZ)
    blocks = [compress(data[i:i + BLOCK]) for i in range(0, len(data), BLOCK)]
    return h(len(blocks), BLOCK, len(data) % BLOCK, *[len(b) for b in blocks]), b''.join(blocks)


def vtu_matrix_file(order, header, layout, compressor):
    o = '<' if order == 'le' else '>'
    header_fmt = 'I' if header == 'u32' else 'Q'
    data = [('Points', 'Float64', struct.pack(o + '15d', *POINTS), 3),
            ('connectivity', 'Int64', struct.pack(o + '11q', *CONN), 1),
            ('offsets', 'Int32', struct.pack(o + '3i', *OFFSETS), 1),
            ('types', 'UInt8', bytes(TYPES), 1)]
    tags = []
    blob = b''
    for name, vtype, values, ncomp in data:
        head, body = vtu_block(values, o, header_fmt, compressor)
        if layout == 'inline':
            # VTK encodes a compressed array's header and its blocks as two base64 streams.
            text = base64.b64encode(head).decode() + base64.b64encode(body).decode()
            tags.append(tag(name, vtype, ncomp, 'binary', text))
        else:
            chunk = head + body if layout == 'raw' else base64.b64encode(head) + base64.b64encode(body)
            tags.append(tag(name, vtype, ncomp, 'appended', offset=len(blob)))
            blob += chunk
    appended_data = b''
    if layout != 'inline':
        encoding = b'raw' if layout == 'raw' else b'base64'
        appended_data = b'  <AppendedData encoding="' + encoding + b'">\n   _' + blob + b'\n  </AppendedData>\n'
    text = document('UInt32' if header == 'u32' else 'UInt64', tags, appended_data,
                    '' if compressor == 'none' else
                    'vtkZLibDataCompressor' if compressor == 'zlib' else 'vtkLZMADataCompressor')
    if order == 'be':
        text = text.replace(b'byte_order="LittleEndian"', b'byte_order="BigEndian"')
    return text


# ---- legacy VTK BINARY (big-endian) ------------------------------------------------------------

def vtk_binary_v3():
    out = b'# vtk DataFile Version 3.0\nbinary v3\nBINARY\nDATASET UNSTRUCTURED_GRID\n'
    out += b'FIELD FieldData 2\nTIME 1 1 double\n' + struct.pack('>d', 1.5) + b'\n'
    out += b'flags 1 10 bit\n' + b'\xff\x03' + b'\n'
    out += b'POINTS 5 float\n' + struct.pack('>15f', *POINTS) + b'\n'
    records = [4, 0, 1, 2, 3, 3, 1, 2, 3, 4, 1, 2, 3, 4]
    out += b'CELLS 3 14\n' + struct.pack('>14i', *records) + b'\n'
    out += b'CELL_TYPES 3\n' + struct.pack('>3i', 10, 5, 10) + b'\n'
    out += b'CELL_DATA 3\nSCALARS id int 1\nLOOKUP_TABLE default\n' + struct.pack('>3i', 7, 8, 9) + b'\n'
    return out


def vtk_binary_v51():
    out = b'# vtk DataFile Version 5.1\nbinary v5.1, as meshio writes\nBINARY\nDATASET UNSTRUCTURED_GRID\n'
    out += b'POINTS 5 double\n' + struct.pack('>15d', *POINTS) + b'\n'
    out += b'CELLS 4 11\nOFFSETS vtktypeint64\n' + struct.pack('>4q', 0, *OFFSETS) + b'\n'
    out += b'CONNECTIVITY vtktypeint64\n' + struct.pack('>11q', *CONN) + b'\n'
    out += b'CELL_TYPES 3\n' + struct.pack('>3i', *TYPES) + b'\n'
    return out


# A tetrahedron's surface: A B C D, faces outward.
SURFACE_POINTS = POINTS[:12]
FACES = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]


def vtk_polydata(binary, strips):
    def ints(values):
        return struct.pack('>%di' % len(values), *values) + b'\n' if binary else \
            (' '.join(map(str, values)) + '\n').encode()
    out = b'# vtk DataFile Version 3.0\ntetrahedron surface\n' + (b'BINARY' if binary else b'ASCII')
    out += b'\nDATASET POLYDATA\nPOINTS 4 double\n'
    out += struct.pack('>12d', *SURFACE_POINTS) + b'\n' if binary else (' '.join(map(str, SURFACE_POINTS)) + '\n').encode()
    if strips:
        # The strip 0 2 1 3 is the faces 0 2 1 and (turned) 1 2 3; two polygons are the others.
        out += b'TRIANGLE_STRIPS 1 5\n' + ints([4, 0, 2, 1, 3])
        out += b'POLYGONS 2 8\n' + ints([3, 0, 1, 3, 3, 0, 3, 2])
    else:
        out += b'POLYGONS 4 16\n' + ints([v for f in FACES for v in [3] + f])
    out += b'LINES 1 3\n' + ints([2, 0, 1])
    return out


def vtp_surface():
    conn = [v for f in FACES for v in f]
    return ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian">\n'
            '  <PolyData>\n    <Piece NumberOfPoints="4" NumberOfPolys="4" NumberOfLines="0">\n'
            '      <Points>\n' +
            tag('Points', 'Float64', 3, 'binary',
                base64.b64encode(struct.pack('<I', 96) + struct.pack('<12d', *SURFACE_POINTS)).decode()) +
            '      </Points>\n      <Polys>\n' +
            tag('connectivity', 'Int32', 1, 'ascii', ' '.join(map(str, conn))) +
            tag('offsets', 'Int32', 1, 'ascii', '3 6 9 12') +
            '      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n').encode()


# ---- Gmsh binary --------------------------------------------------------------------------------

def msh22_binary(order):
    o = '<' if order == 'le' else '>'
    out = b'$MeshFormat\n2.2 1 8\n' + struct.pack(o + 'i', 1) + b'\n$EndMeshFormat\n'
    out += b'$PhysicalNames\n1\n3 1 "volume"\n$EndPhysicalNames\n'
    ids = [10, 20, 30, 40, 50]  # sparse node ids
    out += b'$Nodes\n5\n'
    for i in range(5):
        out += struct.pack(o + 'i3d', ids[i], *POINTS[3 * i:3 * i + 3])
    out += b'\n$EndNodes\n$Elements\n3\n'
    out += struct.pack(o + '3i', 4, 1, 2) + struct.pack(o + '7i', 1, 1, 1, 10, 20, 30, 40)
    out += struct.pack(o + '3i', 2, 1, 3) + struct.pack(o + '7i', 2, 1, 1, 0, 10, 20, 30)
    out += struct.pack(o + '3i', 4, 1, 2) + struct.pack(o + '7i', 3, 1, 1, 20, 30, 40, 50)
    return out + b'\n$EndElements\n'


def msh41_binary(order, size_t):
    o = '<' if order == 'le' else '>'
    z = 'Q' if size_t == 8 else 'I'
    S = lambda *v: struct.pack(o + z * len(v), *v)
    I = lambda *v: struct.pack(o + 'i' * len(v), *v)
    D = lambda *v: struct.pack(o + 'd' * len(v), *v)
    out = b'$MeshFormat\n4.1 1 %d\n' % size_t + I(1) + b'\n$EndMeshFormat\n'
    # Entities: 1 point, 0 curves, 1 surface, 1 volume, with physical tags and bounding entities.
    out += b'$Entities\n' + S(1, 0, 1, 1)
    out += I(1) + D(0, 0, 0) + S(1) + I(5)
    out += I(1) + D(0, 0, 0, 1, 1, 0) + S(0) + S(0)
    out += I(1) + D(0, 0, 0, 1, 1, 1) + S(1) + I(7) + S(1) + I(1)
    out += b'\n$EndEntities\n'
    # Nodes: a surface block, parametric (u v after x y z), with A B C; a volume block with D E.
    out += b'$Nodes\n' + S(2, 5, 1, 9)
    out += I(2, 1, 1) + S(3) + S(1, 2, 3) + b''.join(D(*POINTS[3 * i:3 * i + 3], 0.5, 0.25) for i in range(3))
    out += I(3, 1, 0) + S(2) + S(8, 9) + D(*POINTS[9:15])
    out += b'\n$EndNodes\n'
    out += b'$Elements\n' + S(2, 3, 1, 3)
    out += I(2, 1, 2) + S(1) + S(1, 1, 2, 3)
    out += I(3, 1, 4) + S(2) + S(2, 1, 2, 3, 8) + S(3, 2, 3, 8, 9)
    return out + b'\n$EndElements\n'


def binary_matrix():
    os.makedirs('binary', exist_ok=True)
    for order in ('le', 'be'):
        for header in ('u32', 'u64'):
            for layout in ('inline', 'raw', 'b64'):
                for compressor in ('none', 'zlib', 'lzma'):
                    name = 'binary/vtu_%s_%s_%s_%s.vtu' % (order, header, layout, compressor)
                    open(name, 'wb').write(vtu_matrix_file(order, header, layout, compressor))
    open('binary/two_tets_binary_v3.vtk', 'wb').write(vtk_binary_v3())
    open('binary/two_tets_binary_v51.vtk', 'wb').write(vtk_binary_v51())
    open('binary/tetra_surface_binary.vtk', 'wb').write(vtk_polydata(True, False))
    open('binary/tetra_surface_strips_binary.vtk', 'wb').write(vtk_polydata(True, True))
    open('binary/tetra_surface_ascii.vtk', 'wb').write(vtk_polydata(False, False))
    open('binary/tetra_surface.vtp', 'wb').write(vtp_surface())
    for order in ('le', 'be'):
        open('binary/two_tets_msh22_binary_%s.msh' % order, 'wb').write(msh22_binary(order))
        open('binary/two_tets_msh41_binary_%s.msh' % order, 'wb').write(msh41_binary(order, 8))
    open('binary/two_tets_msh41_binary_size4.msh', 'wb').write(msh41_binary('le', 4))


def main():
    open('two_tets_binary_uint32.vtu', 'wb').write(document('', inline('I', 'f', 'i', False)))
    open('two_tets_binary_uint64.vtu', 'wb').write(document('UInt64', inline('Q', 'd', 'q', True)))
    body, blob = appended('raw')
    open('two_tets_appended_raw.vtu', 'wb').write(document('UInt32', body, blob))
    body, blob = appended('base64')
    open('two_tets_appended_base64.vtu', 'wb').write(document('UInt32', body, blob))
    binary_matrix()


main()
