#!/usr/bin/env bash
# Every named parameter the package reads is documented in the manual's tables of named
# parameters, with its default, and every documented one is read: the package's own
# (declared in internal/parameters_interface.h, read as internal_np::TAG) against the
# first table, CGAL's (read as CGAL::internal_np::TAG, or through GetGeomTraits and
# GetVertexPointMap) against the second, named as CGAL's parameters_interface.h names them.
#
# Then the per-function documentation: every public function (and constructor) that
# takes named parameters documents them in a \cgalNamedParamsBegin block whose entries
# (\cgalParamNBegin{x} ... \cgalParamNEnd) each have a description, a type and a default,
# name a known named parameter, give the manual table's default, and are exactly the
# named parameters that the code reads for that call. What a function reads is derived
# from the code: the tags its own definition names, plus, transitively, those of every
# definition templated on NamedParameters (internal helpers, constructors, other public
# functions) that it passes its pack to (see `reads` below).
# Run by ctest with FS_SOURCE_DIR set.
set -euo pipefail
: "${FS_SOURCE_DIR:?FS_SOURCE_DIR must be set (the source folder)}"
python3 - "$FS_SOURCE_DIR" <<'PY'
import glob, os, re, sys

src = sys.argv[1]
inc = os.path.join(src, "include", "CGAL", "Feature_segmentation")
manual = open(os.path.join(src, "doc", "Feature_segmentation", "Feature_segmentation.txt")).read()
cgal_interface = "/usr/include/CGAL/STL_Extension/internal/parameters_interface.h"

# the package's tags: (tag, function name)
ours = dict(re.findall(r"FS_add_named_parameter\(\w+,\s*(\w+),\s*(\w+)\)",
                       open(os.path.join(inc, "internal", "parameters_interface.h")).read()))
cgal = dict(re.findall(r"CGAL_add_named_parameter\(\w+,\s*(\w+),\s*(\w+)\)", open(cgal_interface).read()))

def tags_of(text):
    """The named parameters that a piece of code reads directly."""
    found = set()
    for prefix, tag in re.findall(r"(CGAL::)?\binternal_np::(\w+?)(?:_t)?\b", text):
        if tag in ours and not prefix: found.add(ours[tag])
        elif prefix and tag in cgal: found.add(cgal[tag])
    if re.search(r"\bGetGeomTraits\s*<", text): found.add("geom_traits")
    if re.search(r"\bGetVertexPointMap\s*<", text): found.add("vertex_point_map")
    return found

code = ""
for path in glob.glob(os.path.join(inc, "**", "*.h"), recursive=True):
    if os.path.basename(path) not in ("parameters.h", "parameters_interface.h"):
        code += open(path).read()
read_all = tags_of(code)
read_ours = read_all & set(ours.values())
read_cgal = read_all & set(cgal.values())

def table(after):
    """The rows (name -> default) of the first table after the line starting with `after`."""
    i = manual.index(after)
    rows, started = {}, False
    for line in manual[i:].splitlines()[1:]:
        if line.startswith("|"):
            started = True
            cells = [c.strip() for c in line.strip("|").split("|")]
            m = re.fullmatch(r"`(\w+)`", cells[0])
            if m: rows[m.group(1)] = cells[2] if after.startswith("The package") else cells[1]
        elif started:
            break
    return rows

documented_ours = table("The package's named parameters")
documented_cgal = table("CGAL's named parameters that the package reads")
failed = 0
def check(what, ok, detail=""):
    global failed
    print(("ok   " if ok else "FAIL ") + what + (f" ({detail})" if detail and not ok else ""))
    failed += not ok

check(f"the package's {len(ours)} named parameters are all read", read_ours == set(ours.values()),
      "never read: " + ", ".join(sorted(set(ours.values()) - read_ours)))
check("every one is in the manual's table", set(ours.values()) <= set(documented_ours),
      "missing: " + ", ".join(sorted(set(ours.values()) - set(documented_ours))))
check("the table holds no other", set(documented_ours) <= set(ours.values()),
      "unknown: " + ", ".join(sorted(set(documented_ours) - set(ours.values()))))
check(f"CGAL's named parameters read ({', '.join(sorted(read_cgal))}) are those of the second table",
      read_cgal == set(documented_cgal), "read: " + ", ".join(sorted(read_cgal)) + "; documented: " +
      ", ".join(sorted(documented_cgal)))
empty = [n for n, d in {**documented_ours, **documented_cgal}.items() if not d]
check("every documented parameter has a default", not empty, ", ".join(empty))

# ---------------------------------------------------------------------------------------
# What each definition templated on NamedParameters reads.
#
# The headers (internal/ included) are read with comments and literals blanked, and cut
# into tokens. A definition is `template <... NamedParameters ...>` followed by a function
# or constructor with a body; its name is the identifier before its parameter list. Its
# own reads are the tags its text names (tags_of()). It calls a definition D when, in its
# body, a call `callee(args)` passes the pack, i.e. one of the arguments is exactly `np`
# (or `np1`, `np2`, ...: packs the code builds on top of `np`) or the callee's template
# arguments name `NamedParameters` (or `NP1`, `NP2`, ...), and the callee's identifiers
# name D, directly or through a typedef/using (`Engine`, `Precomputation`) or through the
# declared type of a member (`m_engine(tm, np)` with `Engine m_engine;`); declarations
# `Type<...> var(tm, np)` and `std::make_shared<const Type>(tm, np)` are such calls. A
# pack passed inside another call (`f(read_crest_options(np))`) or rebuilt without `np`
# (`CGAL::parameters::vertex_point_map(vpm)`) is not passed to `f`. Overloads of one name
# are one node (their reads are merged). reads(f) is the closure over these calls.
def blank(text):
    """`text` with comments and string/character literals replaced by spaces."""
    out, i, n = list(text), 0, len(text)
    def wipe(a, b):
        for k in range(a, b):
            if out[k] != "\n": out[k] = " "
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i); j = n if j < 0 else j
            wipe(i, j); i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2); j = n if j < 0 else j + 2
            wipe(i, j); i = j
        elif text[i] == '"' or (text[i] == "'" and not (i > 0 and text[i - 1].isalnum())):
            q, j = text[i], i + 1
            while j < n and text[j] != q:
                j += 2 if text[j] == "\\" else 1
            wipe(i + 1, j); i = j + 1
        else:
            i += 1
    return "".join(out)

TOKEN = re.compile(r"[A-Za-z_]\w*|\d[\w.]*|::|->|<=|>=|==|!=|&&|\|\||<<|>>|\S")
IDENT = re.compile(r"[A-Za-z_]\w*")

def match_forward(toks, i, o, c):
    """The index of the token that closes toks[i] (which is `o`), or None."""
    d = 0
    for k in range(i, len(toks)):
        if toks[k][0] == o: d += 1
        elif toks[k][0] == c:
            d -= 1
            if d == 0: return k
        elif o == "<" and toks[k][0] in (";", "{", "}"): return None
    return None

def match_backward(toks, i, o, c):
    """The index of the token that opens toks[i] (which is `c`), or None."""
    d = 0
    for k in range(i, -1, -1):
        if toks[k][0] == c: d += 1
        elif toks[k][0] == o:
            d -= 1
            if d == 0: return k
        elif toks[k][0] in (";", "{", "}"): return None
    return None

defs, aliases, members = [], {}, {}
for path in sorted(glob.glob(os.path.join(inc, "**", "*.h"), recursive=True)):
    if os.path.basename(path) == "parameters_interface.h": continue
    raw = open(path).read()
    text = blank(raw)
    toks = [(m.group(), m.start()) for m in TOKEN.finditer(text)]
    for m in re.finditer(r"\btypedef\b([^;{}]*?)\b(\w+)\s*;", text):
        head = re.sub(r"<.*", "", m.group(1), flags=re.S).split("::")[-1].split()
        if head: aliases.setdefault(m.group(2), set()).add(head[-1])
    for m in re.finditer(r"\busing\s+(\w+)\s*=\s*([^;]+);", text):
        aliases.setdefault(m.group(1), set()).add(re.sub(r"<.*", "", m.group(2), flags=re.S).split("::")[-1].strip())
    for m in re.finditer(r"\b(\w+)\s*(?:<[^;{}()]*>\s*)?\s+(\w+)\s*;", text):
        members.setdefault(m.group(2), set()).add(m.group(1))
    for i, (t, pos) in enumerate(toks):
        if t != "template" or i + 1 >= len(toks) or toks[i + 1][0] != "<": continue
        close = match_forward(toks, i + 1, "<", ">")
        if close is None or "NamedParameters" not in [x for x, _ in toks[i + 1:close + 1]]: continue
        k = close + 1
        while k < len(toks) and toks[k][0] not in ("(", ";", "{"): k += 1
        if k >= len(toks) or toks[k][0] != "(": continue
        rparen = match_forward(toks, k, "(", ")")
        b, depth = rparen + 1, 0
        while b < len(toks):
            x = toks[b][0]
            if x in "([": depth += 1
            elif x in ")]": depth -= 1
            elif depth == 0 and x == ";": b = len(toks); break
            elif depth == 0 and x == "{": break
            b += 1
        if b >= len(toks): continue  # a declaration
        end = match_forward(toks, b, "{", "}")
        # the Doxygen comment (/// lines) just above the template line
        doc, j = [], raw.rfind("\n", 0, pos) + 1
        while j > 0:
            prev = raw.rfind("\n", 0, j - 1) + 1
            if not raw[prev:j - 1].strip().startswith("///"): break
            doc.insert(0, raw[prev:j - 1].strip()[3:])
            j = prev
        defs.append(dict(name=toks[k - 1][0], where=f"{os.path.relpath(path, inc)}:{raw.count(chr(10), 0, pos) + 1}",
                         public="internal" not in os.path.relpath(path, inc).split(os.sep),
                         doc="\n".join(doc) if doc else None, text=text[pos:toks[end][1] + 1],
                         toks=toks[k + 1:end + 1]))

def resolve(ident, seen):
    """The names an identifier may stand for: itself, the type it aliases, its member's type."""
    if ident in seen: return set()
    seen.add(ident)
    out = {ident}
    for t in aliases.get(ident, set()) | members.get(ident, set()):
        out |= resolve(t, seen)
    return out

names = {d["name"] for d in defs}
for d in defs:
    d["calls"], toks = set(), d["toks"]
    for i, (t, _) in enumerate(toks):
        if t != "(" or i == 0: continue
        callee, tmpl, j = [], [], i - 1
        while j >= 0:
            x = toks[j][0]
            if x == ">":
                o = match_backward(toks, j, "<", ">")
                if o is None: break
                tmpl += [y for y, _ in toks[o:j + 1]]
                j = o - 1
            elif x == "::" or IDENT.fullmatch(x):
                callee.append(x); j -= 1
            else:
                break
        close = match_forward(toks, i, "(", ")")
        if not callee or close is None: continue
        args, cur, depth = [], [], 0
        for y, _ in toks[i + 1:close]:
            if y in "([{": depth += 1
            elif y in ")]}": depth -= 1
            if y == "," and depth == 0: args.append(cur); cur = []
            else: cur.append(y)
        args.append(cur)
        if any(len(a) == 1 and re.fullmatch(r"np\d*", a[0]) for a in args) or \
           any(re.fullmatch(r"NamedParameters|NP\d+", y) for y in tmpl):
            for ident in callee + [y for y in tmpl if IDENT.fullmatch(y)]:
                d["calls"] |= resolve(ident, set()) & names

reads = {n: set() for n in names}
for d in defs: reads[d["name"]] |= tags_of(d["text"])
changed = True
while changed:
    changed = False
    for d in defs:
        for c in d["calls"]:
            if not reads[c] <= reads[d["name"]]:
                reads[d["name"]] |= reads[c]; changed = True

# ---------------------------------------------------------------------------------------
# The \cgalNamedParamsBegin blocks of the public headers.
def braced(text, start):
    """The text between the brace at `start` and its match."""
    depth = 0
    for k in range(start, len(text)):
        depth += {"{": 1, "}": -1}.get(text[k], 0)
        if depth == 0: return text[start + 1:k]
    return None

def entries(doc):
    """name -> {Description, Type, Default: [texts]} of the \cgalParamNBegin entries in `doc`."""
    out = []
    for m in re.finditer(r"\\cgalParamNBegin\{(\w*)\}(.*?)(?=\\cgalParamNEnd|\\cgalParamNBegin|\\cgalNamedParamsEnd|$)",
                         doc, re.S):
        fields = {}
        for f in ("Description", "Type", "Default"):
            fields[f] = [braced(doc, m.start(2) + k.end() - 1)
                         for k in re.finditer(r"\\cgalParam" + f + r"\{", m.group(2))]
        ended = doc.startswith("\\cgalParamNEnd", m.end())
        out.append((m.group(1), fields, ended))
    return out

known = set(ours.values()) | set(cgal.values())
bad, count = [], 0
for path in sorted(glob.glob(os.path.join(inc, "*.h")) + glob.glob(os.path.join(inc, "IO", "*.h"))):
    rel = os.path.relpath(path, inc)
    # the doc comments only; a line of code ends a comment block
    doc = "\n".join(l.strip()[3:] if l.strip().startswith("///") else "\f" for l in open(path).read().split("\n"))
    for m in re.finditer(r"\\cgalNamedParamsBegin(.*?)(\\cgalNamedParamsEnd|\f|$)", doc, re.S):
        if m.group(2) != "\\cgalNamedParamsEnd":
            bad.append(f"{rel}: a \\cgalNamedParamsBegin without \\cgalNamedParamsEnd in its comment")
    if doc.count("\\cgalNamedParamsBegin") != doc.count("\\cgalNamedParamsEnd"):
        bad.append(f"{rel}: unbalanced \\cgalNamedParamsBegin/End")
    for name, fields, ended in entries(doc):
        count += 1
        if name not in known: bad.append(f"{rel}: {name or '(empty)'} is not a named parameter")
        if not ended: bad.append(f"{rel}: {name}: no \\cgalParamNEnd")
        for f, texts in fields.items():
            if len(texts) != 1 or texts[0] is None or not texts[0].strip():
                bad.append(f"{rel}: {name}: {len(texts)} \\cgalParam{f}" + ("" if len(texts) != 1 else " (empty)"))
    if "bgl_namedparameters" in doc:
        bad.append(f"{rel}: refers to bgl_namedparameters, an anchor of CGAL's manual, not of this one")
check(f"the {count} \\cgalParamNBegin entries of the public headers each have a Description, a Type and a "
      "Default, and name a known named parameter", count > 0 and not bad, "; ".join(bad))

# ---------------------------------------------------------------------------------------
# Every documented public function with named parameters documents exactly what it reads.
documented = [d for d in defs if d["public"] and d["doc"] is not None]
checked = set()
for d in documented:
    label = f"{d['name']}() ({d['where']})"
    if "\\cgalNamedParamsBegin" not in d["doc"]:
        check(f"{label} documents its named parameters in a \\cgalNamedParamsBegin block", False, "no block")
        continue
    doc_names = [n for n, _, _ in entries(d["doc"])]
    have, want = set(doc_names), reads[d["name"]]
    checked.add(d["name"])
    check(f"{label} documents the {len(want)} named parameter{'s' if len(want) != 1 else ''} it reads",
          have == want and
          len(doc_names) == len(have),
          "; ".join(x for x in ("documented but not read: " + ", ".join(sorted(have - want)) if have - want else "",
                                "read but not documented: " + ", ".join(sorted(want - have)) if want - have else "",
                                "listed twice: " + ", ".join(sorted({n for n in doc_names if doc_names.count(n) > 1}))
                                if len(doc_names) != len(have) else "") if x))
check("the segmentation and the editing class are among them (the parse found them)",
      {"segment_along_features", "Feature_aligned_segmentation"} <= checked,
      "checked: " + ", ".join(sorted(checked)))
reached = set().union(*(reads[n] for n in checked)) if checked else set()
check("every named parameter that the code reads is read through some documented function",
      reached == read_all, "not reached: " + ", ".join(sorted(read_all - reached)))

# ---------------------------------------------------------------------------------------
# Every block's default agrees with the manual table's: the same constants, numbers and
# code (`...`), or, for a default in words, the same words.
def key_tokens(cell):
    cell = re.sub(r"\\link\s+\S+\s+(.*?)\\endlink", r"`\1`", cell)
    cell = re.sub(r"</?code>", "", cell)
    cell = re.sub(r"10\^\{(-?\d+)\}", r"1e\1", cell)
    codes = re.findall(r"`([^`]+)`", cell)
    numbers = {float(x) for x in re.findall(r"(?<![\w.])\d+(?:\.\d+)?(?:e[-+]?\d+)?(?![\w.])", cell)}
    words = re.sub(r"\\f\$|[`*]", "", cell).strip().lower()
    return codes, numbers, words

mismatch, compared = [], 0
for d in documented:
    for name, fields, _ in entries(d["doc"] or ""):
        row = documented_ours.get(name, documented_cgal.get(name))
        if row is None or len(fields["Default"]) != 1 or fields["Default"][0] is None: continue
        compared += 1
        block_default = fields["Default"][0]
        codes, numbers, words = key_tokens(row)
        _, block_numbers, block_words = key_tokens(block_default)
        missing = [c for c in codes if c not in block_default] + \
                  [str(n) for n in sorted(numbers - block_numbers)]
        if not codes and not numbers and words not in block_words:
            missing.append(words)
        if missing:
            mismatch.append(f"{d['name']}: {name}: '{' '.join(block_default.split())}' lacks {', '.join(missing)}")
check(f"the {compared} block defaults agree with the manual's tables", compared > 0 and not mismatch,
      "; ".join(mismatch))
sys.exit(1 if failed else 0)
PY
