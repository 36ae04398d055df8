"""lcm-gen's type fingerprint (lcmgen.c: lcm_struct_hash, and the generated _computeHash),
for lcm_schema_gen.py. Members are read by lcm_schema_gen's parser: .name, .type_name, .dims
(strings: a number for a fixed dimension, a member name for a variable one), .primitive.
"""

MASK64 = (1 << 64) - 1


def signed64(v):
    v &= MASK64
    return v - (1 << 64) if v >> 63 else v


def signed_char(c):
    c &= 0xFF
    return c - 256 if c > 127 else c


def hash_update(v, c):
    # lcmgen.c: v = ((v << 8) ^ (v >> 55)) + c, on int64_t with a (signed) char c
    return signed64(((v << 8) ^ (v >> 55)) + signed_char(c))


def hash_string(v, s):
    v = hash_update(v, len(s))
    for ch in s.encode():
        v = hash_update(v, ch)
    return v


def base_hash(s):
    v = 0x12345678
    for m in s.members:
        v = hash_string(v, m.name)
        if m.primitive:
            v = hash_string(v, m.type_name)
        v = hash_update(v, len(m.dims))
        for d in m.dims:
            v = hash_update(v, 0 if d.isdigit() else 1)  # LCM_CONST = 0, LCM_VAR = 1
            v = hash_string(v, d)
    return v & MASK64


def fingerprint(name, by_name, parents=()):
    """getHash() of type name: its own hash plus its nested types', rotated left by one bit."""
    if name in parents:
        return 0
    h = base_hash(by_name[name])
    for m in by_name[name].members:
        if not m.primitive:
            h += fingerprint(m.type_name, by_name, parents + (name,))
    h &= MASK64
    return ((h << 1) + ((h >> 63) & 1)) & MASK64
