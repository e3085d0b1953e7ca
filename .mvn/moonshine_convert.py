# Over 300 lines, on purpose: one standard-library script reads ONNX Runtime's FlatBuffer, rewrites the graph and writes
# ONNX's protobuf, so that fetching the model needs nothing but python3.
"""Turns Moonshine base-en's ONNX Runtime files into the two ONNX models HABLA scores grammar phrases with.

    python3 moonshine_convert.py ENCODER.ort DECODER_MERGED.ort OUT_FOLDER

writes OUT_FOLDER/encoder.onnx and OUT_FOLDER/decoder.onnx (docs/methods/speech.md, "The Moonshine model").
Python's standard library only; the same input gives the same bytes, so the repository pins their SHA-256.

The wheel's files keep every weight as 8-bit integers with one scale and offset per matrix, and turn them
back into floats (Cast, Mul, Add) on every run: for the decoder, 40 million weights each utterance, which
was most of its decoding time. What this writes computes the same network:
- a matrix product with such a weight becomes ONNX Runtime's DynamicQuantizeMatMul, which keeps the
  weight in 8 bits and multiplies in 8 bits (the activations quantized per product);
- the token embedding is looked up in 8 bits and only the rows looked up are turned into floats;
- the decoder keeps only the branch of the merged model that runs without a cache (HABLA feeds each
  phrase whole), with inputs input_ids and encoder_hidden_states and the one output logits.
Weights used any other way (the encoder's convolutions) keep their Cast, Mul and Add, which ONNX Runtime
folds into constants once when it loads the model.

The ONNX Runtime file is a FlatBuffer (ONNX Runtime's ort.fbs schema); the output is ONNX's protobuf.
"""

import os
import struct
import sys

# --- reading ONNX Runtime's FlatBuffer ----------------------------------------------------------------------


class Table:
    """One FlatBuffer table: fields by their index in the schema."""

    def __init__(self, buf, pos):
        self.buf = buf
        self.pos = pos
        self.vtable = pos - struct.unpack_from("<i", buf, pos)[0]
        self.vsize = struct.unpack_from("<H", buf, self.vtable)[0]

    def _at(self, field):
        slot = 4 + 2 * field
        if slot >= self.vsize:
            return 0
        off = struct.unpack_from("<H", self.buf, self.vtable + slot)[0]
        return self.pos + off if off else 0

    def scalar(self, field, fmt, default=0):
        at = self._at(field)
        return struct.unpack_from("<" + fmt, self.buf, at)[0] if at else default

    def _deref(self, at):
        return at + struct.unpack_from("<I", self.buf, at)[0]

    def table(self, field):
        at = self._at(field)
        return Table(self.buf, self._deref(at)) if at else None

    def string(self, field):
        at = self._at(field)
        return _string(self.buf, self._deref(at)) if at else ""

    def _vector(self, field):
        at = self._at(field)
        if not at:
            return 0, 0
        start = self._deref(at)
        return start + 4, struct.unpack_from("<I", self.buf, start)[0]

    def tables(self, field):
        start, n = self._vector(field)
        return [Table(self.buf, self._deref(start + 4 * i)) for i in range(n)]

    def strings(self, field):
        start, n = self._vector(field)
        return [_string(self.buf, self._deref(start + 4 * i)) for i in range(n)]

    def scalars(self, field, fmt):
        start, n = self._vector(field)
        return list(struct.unpack_from("<%d%s" % (n, fmt), self.buf, start)) if n else []

    def raw(self, field):
        start, n = self._vector(field)
        return bytes(self.buf[start:start + n])


def _string(buf, at):
    n = struct.unpack_from("<I", buf, at)[0]
    return bytes(buf[at + 4:at + 4 + n]).decode("utf-8")


# Field indices of ort.fbs
SESSION_MODEL = 1
MODEL_IR_VERSION, MODEL_OPSETS, MODEL_GRAPH = 0, 1, 7
OPSET_DOMAIN, OPSET_VERSION = 0, 1
GRAPH_INITIALIZERS, GRAPH_NODES = 0, 2
NODE_NAME, NODE_DOMAIN, NODE_OP_TYPE, NODE_TYPE, NODE_INPUTS, NODE_OUTPUTS, NODE_ATTRIBUTES = 0, 2, 5, 6, 8, 9, 10
ATTR_NAME, ATTR_TYPE, ATTR_F, ATTR_I, ATTR_S, ATTR_T, ATTR_G, ATTR_FLOATS, ATTR_INTS, ATTR_STRINGS = 0, 2, 3, 4, 5, 6, 7, 8, 9, 10
TENSOR_NAME, TENSOR_DIMS, TENSOR_TYPE, TENSOR_RAW, TENSOR_STRINGS, TENSOR_EXTERNAL = 0, 2, 3, 4, 5, 6

FLOAT, INT8, INT64 = 1, 3, 7
A_FLOAT, A_INT, A_STRING, A_TENSOR, A_GRAPH, A_FLOATS, A_INTS, A_STRINGS = 1, 2, 3, 4, 5, 6, 7, 8


class Tensor:
    def __init__(self, name, dims, dtype, raw=b"", strings=()):
        self.name, self.dims, self.dtype, self.raw, self.strings = name, list(dims), dtype, raw, list(strings)


class Node:
    def __init__(self, op, inputs, outputs, name="", domain="", attrs=()):
        self.op, self.inputs, self.outputs, self.name, self.domain = op, list(inputs), list(outputs), name, domain
        self.attrs = list(attrs)  # (name, type, value)


def read_tensor(t):
    if t.scalar(TENSOR_EXTERNAL, "q", -1) > 0:
        sys.exit("moonshine_convert: tensor %s keeps its data outside the file" % t.string(TENSOR_NAME))
    return Tensor(t.string(TENSOR_NAME), t.scalars(TENSOR_DIMS, "q"), t.scalar(TENSOR_TYPE, "i"),
                  t.raw(TENSOR_RAW), [s.encode() for s in t.strings(TENSOR_STRINGS)])


def read_attribute(a):
    kind = a.scalar(ATTR_TYPE, "i")
    name = a.string(ATTR_NAME)
    if kind == A_FLOAT:
        return name, kind, a.scalar(ATTR_F, "f")
    if kind == A_INT:
        return name, kind, a.scalar(ATTR_I, "q")
    if kind == A_STRING:
        return name, kind, a.string(ATTR_S).encode()
    if kind == A_TENSOR:
        return name, kind, read_tensor(a.table(ATTR_T))
    if kind == A_GRAPH:
        return name, kind, read_graph(a.table(ATTR_G))
    if kind == A_FLOATS:
        return name, kind, a.scalars(ATTR_FLOATS, "f")
    if kind == A_INTS:
        return name, kind, a.scalars(ATTR_INTS, "q")
    if kind == A_STRINGS:
        return name, kind, [s.encode() for s in a.strings(ATTR_STRINGS)]
    sys.exit("moonshine_convert: attribute %s of kind %d is not handled" % (name, kind))


def read_graph(g):
    nodes = []
    for n in g.tables(GRAPH_NODES):
        if n.scalar(NODE_TYPE, "i") != 0:
            sys.exit("moonshine_convert: fused node %s" % n.string(NODE_NAME))
        nodes.append(Node(n.string(NODE_OP_TYPE), n.strings(NODE_INPUTS), n.strings(NODE_OUTPUTS), n.string(NODE_NAME),
                          n.string(NODE_DOMAIN), [read_attribute(a) for a in n.tables(NODE_ATTRIBUTES)]))
    return nodes, [read_tensor(t) for t in g.tables(GRAPH_INITIALIZERS)]


def read_model(path):
    with open(path, "rb") as f:
        buf = f.read()
    if buf[4:8] != b"ORTM":
        sys.exit("moonshine_convert: %s is not an ONNX Runtime model file" % path)
    model = Table(buf, struct.unpack_from("<I", buf, 0)[0]).table(SESSION_MODEL)
    opsets = [(o.string(OPSET_DOMAIN), o.scalar(OPSET_VERSION, "q")) for o in model.tables(MODEL_OPSETS)]
    nodes, inits = read_graph(model.table(MODEL_GRAPH))
    return model.scalar(MODEL_IR_VERSION, "q"), opsets, nodes, inits


# --- the rewrite -----------------------------------------------------------------------------------------------


def rewrite(nodes, inits, outputs):
    """The nodes that compute OUTPUTS with 8-bit weights used in 8 bits; returns (nodes, initializers)."""
    by_name = {t.name: t for t in inits}
    made = {o: n for n in nodes for o in n.outputs}

    def scalar(name):
        t = by_name[name]
        return struct.unpack_from("<f", t.raw)[0]

    # weight = scale * (q - zero): Add(Mul(Cast(q), scale), offset), zero = -offset / scale (an integer here)
    weights = {}
    for n in nodes:
        if n.op != "Add" or n.inputs[1] not in by_name or n.inputs[0] not in made:
            continue
        mul = made[n.inputs[0]]
        cast = made.get(mul.inputs[0]) if mul.op == "Mul" else None
        if cast is None or cast.op != "Cast" or cast.inputs[0] not in by_name or mul.inputs[1] not in by_name:
            continue
        scale = scalar(mul.inputs[1])
        zero = -scalar(n.inputs[1]) / scale
        if abs(zero - round(zero)) > 1e-3 or not -128 <= round(zero) <= 127 or by_name[cast.inputs[0]].dtype != INT8:
            sys.exit("moonshine_convert: weight %s is not 8-bit with an integer zero point" % cast.inputs[0])
        weights[n.outputs[0]] = (cast.inputs[0], scale, int(round(zero)))

    extra = []

    def const(name, dtype, raw):
        extra.append(Tensor(name, [], dtype, raw))
        return name

    def quantized(q, scale, zero, suffix=""):
        return [const(q + "_scale" + suffix, FLOAT, struct.pack("<f", scale)),
                const(q + "_zero" + suffix, INT8, struct.pack("<b", zero))]

    transposed = {}
    out = []
    for n in nodes:
        if n.op == "MatMul" and n.inputs[1] in weights:
            q, scale, zero = weights[n.inputs[1]]
            out.append(Node("DynamicQuantizeMatMul", [n.inputs[0], q] + quantized(q, scale, zero), n.outputs, n.name,
                            "com.microsoft"))
        elif n.op == "Transpose" and n.inputs[0] in weights:
            transposed[n.outputs[0]] = (weights[n.inputs[0]], n.attrs)
        elif n.op == "MatMul" and n.inputs[1] in transposed:
            (q, scale, zero), attrs = transposed[n.inputs[1]]
            out.append(Node("Transpose", [q], [q + "_transposed"], attrs=attrs))
            out.append(Node("DynamicQuantizeMatMul", [n.inputs[0], q + "_transposed"] + quantized(q, scale, zero, "_t"),
                            n.outputs, n.name, "com.microsoft"))
        elif n.op == "Gather" and n.inputs[0] in weights:
            q, scale, zero = weights[n.inputs[0]]
            o = n.outputs[0]
            out += [Node("Gather", [q, n.inputs[1]], [o + "_q"], n.name, attrs=n.attrs),
                    Node("Cast", [o + "_q"], [o + "_f"], attrs=[("to", A_INT, FLOAT)]),
                    Node("Sub", [o + "_f", const(o + "_zero", FLOAT, struct.pack("<f", zero))], [o + "_c"]),
                    Node("Mul", [o + "_c", const(o + "_scale", FLOAT, struct.pack("<f", scale))], [o])]
        else:
            out.append(n)
    needed = set(outputs)
    kept = []
    for n in reversed(out):
        if any(o in needed for o in n.outputs):
            if any(kind == A_GRAPH for _, kind, _ in n.attrs):
                sys.exit("moonshine_convert: node %s holds a graph" % n.name)
            kept.append(n)
            needed.update(i for i in n.inputs if i)
    kept.reverse()
    return kept, [t for t in inits + extra if t.name in needed]


def decoder_without_cache(nodes, inits):
    """The merged decoder's branch without a cache, with the outer nodes it reads from."""
    branch = [n for n in nodes if n.op == "If"]
    if len(branch) != 1:
        sys.exit("moonshine_convert: the decoder is not a merged model with one If")
    body_nodes, body_inits = next(v for name, _, v in branch[0].attrs if name == "else_branch")
    return [n for n in nodes if n.op != "If"] + body_nodes, inits + body_inits


# --- writing ONNX's protobuf ------------------------------------------------------------------------------------


def varint(v):
    v &= (1 << 64) - 1
    out = bytearray()
    while True:
        b = v & 0x7F
        v >>= 7
        if v:
            out.append(b | 0x80)
        else:
            out.append(b)
            return bytes(out)


def field_varint(num, v):
    return varint(num << 3) + varint(v)


def field_bytes(num, data):
    return varint(num << 3 | 2) + varint(len(data)) + data


def field_str(num, s):
    return field_bytes(num, s.encode("utf-8"))


def tensor_proto(t):
    b = b"".join(field_varint(1, d) for d in t.dims) + field_varint(2, t.dtype)
    b += b"".join(field_bytes(6, s) for s in t.strings)
    b += field_str(8, t.name)
    if not t.strings:
        b += field_bytes(9, t.raw)
    return b


def attribute_proto(name, kind, value):
    b = field_str(1, name)
    if kind == A_FLOAT:
        b += varint(2 << 3 | 5) + struct.pack("<f", value)
    elif kind == A_INT:
        b += field_varint(3, value)
    elif kind == A_STRING:
        b += field_bytes(4, value)
    elif kind == A_TENSOR:
        b += field_bytes(5, tensor_proto(value))
    elif kind == A_FLOATS:
        b += field_bytes(7, b"".join(struct.pack("<f", f) for f in value))
    elif kind == A_INTS:
        b += field_bytes(8, b"".join(varint(i) for i in value))
    elif kind == A_STRINGS:
        b += b"".join(field_bytes(9, s) for s in value)
    return b + field_varint(20, kind)


def node_proto(n):
    b = b"".join(field_str(1, i) for i in n.inputs) + b"".join(field_str(2, o) for o in n.outputs)
    b += field_str(3, n.name) + field_str(4, n.op)
    b += b"".join(field_bytes(5, attribute_proto(*a)) for a in n.attrs)
    return b + field_str(7, n.domain)


def value_info(name, elem, dims):
    shape = b"".join(field_bytes(1, field_varint(1, d) if isinstance(d, int) else field_str(2, d)) for d in dims)
    tensor_type = field_varint(1, elem) + field_bytes(2, shape)
    return field_str(1, name) + field_bytes(2, field_bytes(1, tensor_type))


def model_proto(ir_version, opsets, nodes, inits, inputs, outputs):
    g = b"".join(field_bytes(1, node_proto(n)) for n in nodes) + field_str(2, "main")
    g += b"".join(field_bytes(5, tensor_proto(t)) for t in inits)
    g += b"".join(field_bytes(11, value_info(*i)) for i in inputs)
    g += b"".join(field_bytes(12, value_info(*o)) for o in outputs)
    m = field_varint(1, ir_version) + field_str(2, "habla moonshine_convert")
    m += field_bytes(7, g)
    m += b"".join(field_bytes(8, field_str(1, d) + field_varint(2, v)) for d, v in opsets)
    return m


def convert(source, target, inputs, outputs, merged):
    ir_version, opsets, nodes, inits = read_model(source)
    if merged:
        nodes, inits = decoder_without_cache(nodes, inits)
    if not any(d == "com.microsoft" for d, _ in opsets):
        opsets.append(("com.microsoft", 1))
    nodes, inits = rewrite(nodes, inits, [o[0] for o in outputs])
    tmp = target + ".part"
    with open(tmp, "wb") as f:
        f.write(model_proto(ir_version, opsets, nodes, inits, inputs, outputs))
    os.replace(tmp, target)


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: moonshine_convert.py ENCODER.ort DECODER_MERGED.ort OUT_FOLDER")
    encoder, decoder, out = sys.argv[1:]
    convert(encoder, os.path.join(out, "encoder.onnx"), [("input_values", FLOAT, ["batch", "samples"])],
            [("last_hidden_state", FLOAT, ["batch", "frames", 416])], merged=False)
    convert(decoder, os.path.join(out, "decoder.onnx"),
            [("input_ids", INT64, ["batch", "steps"]), ("encoder_hidden_states", FLOAT, ["batch", "frames", 416])],
            [("logits", FLOAT, ["batch", "steps", 32768])], merged=True)


if __name__ == "__main__":
    main()
