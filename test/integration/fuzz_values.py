"""Hostile values for the fuzz tests (test_fuzz.py, test_fuzz_physics.py): a valid message with
one leaf, or one array's length, replaced by a value drawn from that leaf type's hostile values."""
import genpy

FLOATS = [float("nan"), float("inf"), -float("inf"), 1e300, -1e300, 1e-300, 0.0, -1.0, 1e6,
          -1e6, 3.4e38]
FLOATS32 = [float("nan"), float("inf"), -float("inf"), 3.4e38, -3.4e38, 1e-38, 0.0, -1.0, 1e6]
STRINGS = ["", " ", "x" * 5000, "h\u00e9llo \u4f60\u597d", "\n\t", "human10", "../../etc/passwd",
           "anonymous_person_abcde", "QUESTION:TIME", "%s%s%n", "g1"]
INT_LIMITS = {"int8": (-2**7, 2**7 - 1), "uint8": (0, 2**8 - 1), "int16": (-2**15, 2**15 - 1),
              "uint16": (0, 2**16 - 1), "int32": (-2**31, 2**31 - 1), "uint32": (0, 2**32 - 1),
              "int64": (-2**63, 2**63 - 1), "uint64": (0, 2**64 - 1)}


def leaves(msg, path=""):
    """(path, type, parent, slot or index) of every scalar of `msg`, and of each array itself."""
    found = []
    for slot, slot_type in zip(msg.__slots__, msg._slot_types):
        value = getattr(msg, slot)
        name = path + slot
        if slot_type.endswith("]"):
            if slot_type.endswith("[]"):  # a fixed-size array (a covariance) keeps its length
                found.append((name + "[]", "array", msg, slot))
            item_type = slot_type[:slot_type.index("[")]
            if item_type in ("uint8", "char"):  # bytes: only the length is fuzzed
                continue
            # Every item of a message array; the ends of a long array of numbers (a map's cells).
            indices = range(len(value)) if len(value) <= 50 else (0, len(value) - 1)
            if not isinstance(value, list):
                value = list(value)
                setattr(msg, slot, value)
            for i in indices:
                item = value[i]
                if hasattr(item, "__slots__"):
                    found += leaves(item, "%s[%d]." % (name, i))
                else:
                    found.append(("%s[%d]" % (name, i), item_type, value, i))
        elif hasattr(value, "__slots__") and slot_type not in ("time", "duration"):
            found += leaves(value, name + ".")
        else:
            found.append((name, slot_type, msg, slot))
    return found


def hostile(rng, kind, current):
    if kind in ("float32", "float64"):
        return rng.choice((FLOATS32 if kind == "float32" else FLOATS) + [rng.uniform(-100, 100)])
    if kind in INT_LIMITS:
        low, high = INT_LIMITS[kind]
        return rng.choice([low, high, 0, 1, rng.randint(low, high)])
    if kind == "string":
        return rng.choice(STRINGS)
    if kind == "bool":
        return not current
    if kind in ("time", "duration"):
        cls = genpy.Time if kind == "time" else genpy.Duration
        return cls(rng.choice([0, 1, 2**31 - 1]), rng.choice([0, 999999999]))
    return current


def mutate(rng, msg):
    """`msg` with one leaf (or one array's length) replaced by a hostile value; the leaf's path."""
    path, kind, parent, key = rng.choice(leaves(msg))
    if kind == "array":
        items = getattr(parent, key)
        template = items[0] if items else None
        length = rng.choice([0, 1, 3, 300])
        setattr(parent, key, [] if template is None else [template] * length)
        return path
    if isinstance(parent, list):
        parent[key] = hostile(rng, kind, parent[key])
    else:
        setattr(parent, key, hostile(rng, kind, getattr(parent, key)))
    return path
