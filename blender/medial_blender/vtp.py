"""VTK XML PolyData (.vtp) read and written in pure Python (numpy, zlib), so that Blender never loads VTK.

Reads what the `medial` command writes (vtkXMLPolyDataWriter: inline base64 "binary" arrays, zlib
compressed, UInt32 or UInt64 headers) and ASCII arrays; writes ASCII files, which vtkXMLPolyDataReader
reads. The format: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html
"""
import base64
import math
import xml.etree.ElementTree as ElementTree
import zlib

import numpy

_TYPES = {"Int8": "i1", "UInt8": "u1", "Int16": "i2", "UInt16": "u2", "Int32": "i4", "UInt32": "u4",
          "Int64": "i8", "UInt64": "u8", "Float32": "f4", "Float64": "f8"}


class PolyData:
    """points (n x 3), lines and polys (lists of index arrays), point_data and field_data (name -> array,
    n x components or n)."""

    def __init__(self, points=None, lines=None, polys=None, point_data=None, field_data=None):
        self.points = numpy.zeros((0, 3)) if points is None else numpy.asarray(points, dtype=float)
        self.lines = lines or []
        self.polys = polys or []
        self.point_data = point_data or {}
        self.field_data = field_data or {}

    def segments(self):
        """The lines split into 2-point edges, in order: bone i of `medial rig` is segment i."""
        return [(int(line[k]), int(line[k + 1])) for line in self.lines for k in range(len(line) - 1)]


def _decode_binary(text, dtype, header, compressed):
    text = "".join(text.split())
    size = 8 if header == "UInt64" else 4
    header_type = numpy.dtype("<u8" if size == 8 else "<u4")
    if not compressed:
        raw = base64.b64decode(text)
        count = int(numpy.frombuffer(raw[:size], header_type)[0])
        return numpy.frombuffer(raw[size:size + count], dtype)
    blocks = int(numpy.frombuffer(base64.b64decode(text[:4 * math.ceil(size / 3)])[:size], header_type)[0])
    header_chars = 4 * math.ceil((3 + blocks) * size / 3)
    sizes = numpy.frombuffer(base64.b64decode(text[:header_chars])[:(3 + blocks) * size], header_type)
    data = base64.b64decode(text[header_chars:])
    parts, start = [], 0
    for compressed_size in sizes[3:]:
        parts.append(zlib.decompress(data[start:start + int(compressed_size)]))
        start += int(compressed_size)
    return numpy.frombuffer(b"".join(parts), dtype)


def _array(element, root):
    dtype = numpy.dtype(_TYPES[element.get("type")]).newbyteorder(
        "<" if root.get("byte_order", "LittleEndian") == "LittleEndian" else ">")
    form = element.get("format", "ascii")
    if form == "ascii":
        values = numpy.array((element.text or "").split(), dtype=dtype)
    elif form == "binary":
        values = _decode_binary(element.text or "", dtype, root.get("header_type", "UInt32"),
                                root.get("compressor") is not None)
    else:
        raise ValueError("appended .vtp data is not supported; write the file with inline arrays")
    components = int(element.get("NumberOfComponents", "1"))
    return values.reshape(-1, components) if components > 1 else values


def _cells(element, root):
    if element is None:
        return []
    arrays = {a.get("Name"): _array(a, root) for a in element.findall("DataArray")}
    connectivity = numpy.asarray(arrays.get("connectivity", []), dtype=numpy.int64)
    offsets = numpy.asarray(arrays.get("offsets", []), dtype=numpy.int64)
    if len(offsets) == 0:
        return []
    sizes = numpy.diff(offsets, prepend=0)
    if numpy.all(sizes == sizes[0]):  # triangles, or 2-point lines: one reshape
        return connectivity.reshape(-1, int(sizes[0]))
    starts = offsets - sizes
    return [connectivity[start:end] for start, end in zip(starts.tolist(), offsets.tolist())]


def read(path, only=None):
    """The PolyData of the .vtp file at path (one piece). With only (point data names), just those arrays
    are decoded: no points, cells or field data."""
    root = ElementTree.parse(path).getroot()
    if root.get("type") != "PolyData":
        raise ValueError("%s: not a VTK PolyData file" % path)
    poly = root.find("PolyData")
    piece = poly.find("Piece")
    result = PolyData()
    for array in piece.findall("PointData/DataArray"):
        if only is None or array.get("Name") in only:
            result.point_data[array.get("Name")] = _array(array, root)
    if only is not None:
        missing = set(only) - set(result.point_data)
        if missing:
            raise ValueError("%s has no point data %s" % (path, ", ".join(sorted(missing))))
        return result
    points = piece.find("Points/DataArray")
    if points is not None:
        result.points = _array(points, root).astype(float).reshape(-1, 3)
    result.lines = _cells(piece.find("Lines"), root)
    result.polys = _cells(piece.find("Polys"), root)
    for array in poly.findall("FieldData/DataArray"):
        result.field_data[array.get("Name")] = _array(array, root)
    return result


def _ascii_array(name, values, vtk_type, components=1, tuples=None):
    text = " ".join(repr(float(v)) if vtk_type.startswith("Float") else str(int(v))
                    for v in numpy.asarray(values).ravel())
    extra = ' NumberOfTuples="%d"' % tuples if tuples is not None else ""
    return '<DataArray type="%s" Name="%s" NumberOfComponents="%d"%s format="ascii">%s</DataArray>\n' % (
        vtk_type, name, components, extra, text)


def write(path, data):
    """Writes data (a PolyData with points, lines and float point data, int field data) as ASCII .vtp."""
    offsets = numpy.cumsum([len(line) for line in data.lines]) if data.lines else []
    connectivity = numpy.concatenate(data.lines) if data.lines else []
    out = ['<?xml version="1.0"?>\n<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">\n'
           '<PolyData>\n<FieldData>\n']
    for name, values in data.field_data.items():
        out.append(_ascii_array(name, numpy.atleast_1d(values), "Int32", tuples=numpy.size(values)))
    out.append('</FieldData>\n<Piece NumberOfPoints="%d" NumberOfVerts="0" NumberOfLines="%d" NumberOfStrips="0"'
               ' NumberOfPolys="0">\n<PointData>\n' % (len(data.points), len(data.lines)))
    for name, values in data.point_data.items():
        values = numpy.asarray(values, dtype=float)
        out.append(_ascii_array(name, values, "Float64", 1 if values.ndim == 1 else values.shape[1]))
    out.append("</PointData>\n<Points>\n")
    out.append(_ascii_array("Points", data.points, "Float64", 3))
    out.append("</Points>\n<Lines>\n")
    out.append(_ascii_array("connectivity", connectivity, "Int64"))
    out.append(_ascii_array("offsets", offsets, "Int64"))
    out.append("</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n")
    with open(path, "w") as stream:
        stream.write("".join(out))
