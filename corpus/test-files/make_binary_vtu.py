#!/usr/bin/env python3
"""Writes the binary .vtu test files the way VTK lays them out (run from this directory).

Two tets A B C D / B C D E plus a triangle, in: inline base64 with a UInt32 header (one stream
for header and data), inline base64 with a UInt64 header (header and data encoded as two
streams, as VTK does for compressed data), appended raw, appended base64, and a compressed
header that readers must refuse.
"""
import base64
import struct

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


def main():
    open('two_tets_binary_uint32.vtu', 'wb').write(document('', inline('I', 'f', 'i', False)))
    open('two_tets_binary_uint64.vtu', 'wb').write(document('UInt64', inline('Q', 'd', 'q', True)))
    body, blob = appended('raw')
    open('two_tets_appended_raw.vtu', 'wb').write(document('UInt32', body, blob))
    body, blob = appended('base64')
    open('two_tets_appended_base64.vtu', 'wb').write(document('UInt32', body, blob))
    open('two_tets_compressed.vtu', 'wb').write(
        document('UInt32', inline('I', 'f', 'i', False), compressor='vtkZLibDataCompressor'))


main()
