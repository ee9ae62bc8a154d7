#!/usr/bin/env python3
"""Independent oracle for the ABOP conformance tests of ramus.

Computes, for every example in examples/abop/, the exact length (number of modules), the number
of `F` modules and, for the parametric trees of ABOP chapter 2, the sum of the `F` lengths after
n derivation steps, and writes

  tests/expected/abop.tsv          file, steps, length, F count, F length sum or '-'
  tests/expected/abop_strings.tsv  file, steps, the whole derived word (short words only)

This script shares no code with ramus and does not read .ramus files: every L-system is typed in
below from the book (Prusinkiewicz & Lindenmayer, The Algorithmic Beauty of Plants, 1990), in the
book's own notation, so that a wrong production in an example or a wrong rule in the engine makes
the two disagree. How each number is computed:

* Bracketed OL-systems (figs. 1.24a-f, 1.25, the 3D Hilbert curve of fig. 1.10): the word is
  rewritten as a Python string (one character per module), and independently the Parikh vector
  (count of each symbol) is advanced with the production matrix, P_{n+1}[b] = sum_a P_n[a] *
  #b(succ(a)). Length and F count are taken from the Parikh vector; the script stops with an
  error if the rewritten word disagrees with it.
* Context-sensitive systems (fig. 1.31a-e): rewritten as strings with the branch-aware context
  rules of cpfg/ABOP section 1.8: symbols of the ignore set (+ - F) are invisible to contexts; a
  left context skips `[` and whole sibling branches `[...]`; a right context skips lateral
  branches `[...]` and fails at the `]` closing the current branch; a symbol with no context (at
  either end of the word) is copied. The states 0 and 1 of the book are the modules O and I of
  the ramus files.
* The parametric system of ABOP p. 42 (section 1.10.1): rewritten module by module with Python
  floats (IEEE doubles, as the engine uses); the words must equal the five words printed in the
  book (checked below, to the book's 6 decimals).
* Monopodial trees (fig. 2.6a-d): rewritten as parametric words with Python floats; length, F
  count and F length sum are cross-checked against the recurrences over (module, step):
      L_A(n) = 6 + L_B(n-1) + L_A(n-1),  L_B(n) = 6 + 2 L_C(n-1),  L_C(n) = 6 + 2 L_B(n-1)
      S_A(n, l) = l + S_B(n-1, l r2) + S_A(n-1, l r1), and so on (S = sum of F lengths).
* Ternary trees (fig. 2.8a-d): rewritten parametrically, cross-checked against the closed forms
      #A(t) = 3^t,  length(n) = 4 + 18 (3^n - 1) / 2,  #F(n) = 1 + 4 (3^n - 1) / 2,
      sum F(n) = 200 lr^n + sum_{t=1..n} 4 * 3^(t-1) * 50 lr^(n-t).
* Stochastic fig. 1.27: no fixed numbers; every production replaces one F by k F and 3(k-1)/2
  other modules (k = 5 or 3), so length = (5 #F - 3) / 2 after any number of steps. The script
  checks this on random derivations and writes the formula in the length column.

Run from anywhere: python3 tests/tools/abop_oracle.py  (rewrites the two files).
"""

import os
import random
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


# ---- bracketed OL-systems: string rewriting and Parikh vectors ---------------------------------

def rewrite_d0l(word, prods, n):
    for _ in range(n):
        word = "".join(prods.get(c, c) for c in word)
    return word


def parikh_d0l(axiom, prods, n):
    counts = {}
    for c in axiom:
        counts[c] = counts.get(c, 0) + 1
    for _ in range(n):
        nxt = {}
        for a, k in counts.items():
            for b in prods.get(a, a):
                nxt[b] = nxt.get(b, 0) + k
        counts = nxt
    return counts


def d0l_stats(axiom, prods, n):
    counts = parikh_d0l(axiom, prods, n)
    length, fcount = sum(counts.values()), counts.get("F", 0)
    if length < 2_000_000:
        word = rewrite_d0l(axiom, prods, n)
        if len(word) != length or word.count("F") != fcount:
            sys.exit(f"oracle disagrees with itself: {axiom} {prods} n={n}")
    return length, fcount


# ---- context-sensitive rewriting with ABOP's bracket rules --------------------------------------

def bracket_pairs(word):
    match, stack = [-1] * len(word), []
    for i, c in enumerate(word):
        if c == "[":
            stack.append(i)
        elif c == "]":
            j = stack.pop()
            match[i], match[j] = j, i
    return match


def left_context(word, match, i, ignore):
    j = i - 1
    while j >= 0:
        c = word[j]
        if c == "]":
            j = match[j] - 1  # a whole sibling branch
        elif c == "[" or c in ignore:
            j -= 1
        else:
            return c
    return None


def right_context(word, match, i, ignore):
    j = i + 1
    while j < len(word):
        c = word[j]
        if c == "[":
            j = match[j] + 1  # a lateral branch
        elif c == "]":
            return None  # end of the current branch
        elif c in ignore:
            j += 1
        else:
            return c
    return None


def rewrite_2l(word, table, other, ignore, n):
    """table: (left, strict, right) -> successor; other: context-free productions."""
    for _ in range(n):
        match = bracket_pairs(word)
        out = []
        for i, c in enumerate(word):
            if c in other:
                out.append(other[c])
                continue
            key = (left_context(word, match, i, ignore), c, right_context(word, match, i, ignore))
            out.append(table.get(key, c))
        word = "".join(out)
    return word


def hogeweg(rows):
    """rows: successors of 0<0>0, 0<0>1, 0<1>0, ..., 1<1>1 in the book's order."""
    keys = [(a, b, c) for a in "01" for b in "01" for c in "01"]
    return dict(zip(keys, rows))


# ---- parametric words ---------------------------------------------------------------------------

def fmt_num(x):
    """Shortest round-trip form, integers without a decimal point (ramus --print)."""
    if x == int(x) and abs(x) < 1e15:
        return str(int(x))
    return repr(x)


def fmt_word(word):
    out = []
    for sym, params in word:
        out.append(sym + ("(" + ",".join(fmt_num(p) for p in params) + ")" if params else ""))
    return "".join(out)


def rewrite_param(word, rules, n):
    """rules: symbol -> function(params) returning a list of modules or None (no match)."""
    for _ in range(n):
        out = []
        for m in word:
            succ = rules[m[0]](*m[1]) if m[0] in rules else None
            out.extend([m] if succ is None else succ)
        word = out
    return word


def param_stats(word):
    fs = [p[0] for s, p in word if s == "F"]
    return len(word), len(fs), float(sum(fs))


def p42_rules():
    def a(x, y):
        return [("A", (x * 2, x + y))] if y <= 3 else [("B", (x,)), ("A", (x / y, 0.0))]

    def b(x):
        return [("C", ())] if x < 1 else [("B", (x - 1,))]

    return {"A": a, "B": b}


P42_AXIOM = [("B", (2.0,)), ("A", (4.0, 4.0))]
P42_BOOK = ["B(2)A(4,4)", "B(1)B(4)A(1,0)", "B(0)B(3)A(2,1)", "CB(2)A(4,3)", "CB(1)A(8,7)",
            "CB(0)B(8)A(1.142857,0)"]


def m(sym, *params):
    return (sym, tuple(float(p) for p in params))


def monopodial_rules(r1, r2, a0, a2, d=137.5, wr=0.707):
    def a(l, w):
        return [m("!", w), m("F", l), m("["), m("&", a0), m("B", l * r2, w * wr), m("]"),
                m("/", d), m("A", l * r1, w * wr)]

    def bc(turn, nxt):
        def p(l, w):
            return [m("!", w), m("F", l), m("["), m(turn, a2), m("$"), m(nxt, l * r2, w * wr),
                    m("]"), m(nxt, l * r1, w * wr)]
        return p

    return {"A": a, "B": bc("-", "C"), "C": bc("+", "B")}


def monopodial_recurrence(r1, r2, n, l0=1.0):
    """(length, F count, F sum) of A(l0, .) after n steps, by recurrence over the apices."""
    def rec(sym, k, l):
        if k == 0:
            return 1, 0, 0.0
        if sym == "A":
            parts = [rec("B", k - 1, l * r2), rec("A", k - 1, l * r1)]
        else:
            nxt = "C" if sym == "B" else "B"
            parts = [rec(nxt, k - 1, l * r2), rec(nxt, k - 1, l * r1)]
        return (6 + parts[0][0] + parts[1][0], 1 + parts[0][1] + parts[1][1],
                l + parts[0][2] + parts[1][2])
    return rec("A", n, l0)


def ternary_rules(d1, d2, a, lr, vr=1.732):
    def apex():
        branch = [m("["), m("&", a), m("F", 50), m("A"), m("]")]
        return ([m("!", vr), m("F", 50)] + branch + [m("/", d1)] + branch + [m("/", d2)] + branch)

    return {"A": lambda: apex(), "F": lambda l: [m("F", l * lr)], "!": lambda w: [m("!", w * vr)]}


TERNARY_AXIOM = [m("!", 1), m("F", 200), m("/", 45), m("A")]


def ternary_closed_form(lr, n):
    length = 4 + 18 * (3**n - 1) // 2
    fcount = 1 + 4 * (3**n - 1) // 2
    fsum = 200 * lr**n + sum(4 * 3 ** (t - 1) * 50 * lr ** (n - t) for t in range(1, n + 1))
    return length, fcount, fsum


# ---- the examples -------------------------------------------------------------------------------

FIG_1_24 = {  # name: (n, axiom, productions)
    "fig1_24a": (5, "F", {"F": "F[+F]F[-F]F"}),
    "fig1_24b": (5, "F", {"F": "F[+F]F[-F][F]"}),
    "fig1_24c": (4, "F", {"F": "FF-[-F+F+F]+[+F-F-F]"}),
    "fig1_24d": (7, "X", {"X": "F[+X]F[-X]+X", "F": "FF"}),
    "fig1_24e": (7, "X", {"X": "F[+X][-X]FX", "F": "FF"}),
    "fig1_24f": (5, "X", {"X": "F-[[X]+X]+F[+FX]-X", "F": "FF"}),
}
# fig. 1.25 with the leaf polygon {-f+f+f-|-f+f+f} replaced by the organ ~ (see the .ramus file).
FIG_1_25 = (7, "A", {"A": "[&FL!A]/////'[&FL!A]///////'[&FL!A]", "F": "S/////F", "S": "FL",
                     "L": "['''^^{-f+f+f-|-f+f+f}]"})
HILBERT = (2, "A", {"A": "B-F+CFC+F-D&F^D-F+&&CFC+F+B//",
                    "B": "A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//",
                    "C": "|D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//",
                    "D": "|CFB-F+B|FA&F^A&&FB-F+B|FC//"})
FIG_1_31 = {  # name: (n, axiom, successors of 0<0>0 ... 1<1>1)
    "fig1_31a": (30, "F1F1F1", ["0", "1[+F1F1]", "1", "1", "0", "1F1", "0", "0"]),
    "fig1_31b": (30, "F1F1F1", ["1", "1[-F1F1]", "1", "1", "0", "1F1", "1", "0"]),
    "fig1_31c": (26, "F1F1F1", ["0", "1", "0", "1[+F1F1]", "0", "1F1", "0", "0"]),
    "fig1_31d": (24, "F0F1F1", ["1", "0", "0", "1F1", "1", "1[+F1F1]", "1", "0"]),
    "fig1_31e": (26, "F1F1F1", ["0", "1[-F1F1]", "1", "1", "0", "1F1", "1", "0"]),
}
FIG_2_6 = {  # r1, r2, a0, a2
    "fig2_6a_monopodial": (0.9, 0.6, 45, 45),
    "fig2_6b_monopodial": (0.9, 0.9, 45, 45),
    "fig2_6c_monopodial": (0.9, 0.8, 45, 45),
    "fig2_6d_monopodial": (0.9, 0.7, 30, -30),
}
FIG_2_8 = {  # d1, d2, a, lr, n
    "fig2_8a_ternary": (94.74, 132.63, 18.95, 1.109, 6),
    "fig2_8b_ternary": (137.5, 137.5, 18.95, 1.109, 8),
    "fig2_8c_ternary": (112.5, 157.5, 22.5, 1.790, 8),
    "fig2_8d_ternary": (180, 252, 36, 1.070, 6),
}
# Chapter 5 polygons (section 5.2): `{` `.` `}` and G are plain symbols to the rewriter.
FIG_5_5 = (20, "[A][B]", {"A": "[+A{.].C.}", "B": "[-B{.].C.}", "C": "GC"})
LILY_PETAL = [m("["), m("X", 36), m("A"), m("]"), m("/", 72), m("["), m("X", 36), m("B"), m("]")]
LILY_AXIOM = LILY_PETAL * 5  # ramus's flower: the book's one-petal axiom five times around
LILY_N = 18


def lily_rules():
    def a():
        return [m("["), m("&"), m("G"), m("A"), m("{"), m("."), m("]"), m(".")]

    def b():
        return [m("B"), m("&"), m("."), m("G"), m("."), m("}")]

    def x(v):
        return [m("X", v + 4.5)]

    return {"A": a, "B": b, "X": x}


def polygon_counts(word):
    """Counts of { . } G in a word of single-character symbols or of (symbol, params) modules."""
    syms = [w if isinstance(w, str) else w[0] for w in word]
    return tuple(syms.count(c) for c in "{.}G")


MONOPODIAL_W0 = 0.15  # the initial width of the ramus files (the book's is 10 pixels)


def path(name):
    return f"examples/abop/{name}.ramus"


def steps_for(n):
    """The book's n first (the test runs that row without -n), then smaller steps."""
    return [n] + [k for k in (0, 1, 2, 3) if k < n] + ([n - 1] if n - 1 > 3 else [])


def close(a, b, rel=1e-12):
    return abs(a - b) <= rel * max(1.0, abs(a), abs(b))


def collect():
    rows, strings, polygons = [], [], []

    def d0l(name, n, axiom, prods, string_steps=()):
        for k in steps_for(n):
            length, fcount = d0l_stats(axiom, prods, k)
            rows.append((path(name), k, length, fcount, "-"))
        for k in string_steps:
            strings.append((path(name), k, rewrite_d0l(axiom, prods, k)))

    for name, (n, axiom, prods) in FIG_1_24.items():
        d0l(name, n, axiom, prods, (1, 2) if name in ("fig1_24a", "fig1_24f") else ())
    d0l("fig1_25", *FIG_1_25, string_steps=(1, 2))
    d0l("hilbert3d", *HILBERT, string_steps=(1,))
    d0l("fig5_5_cordate_leaf", *FIG_5_5, string_steps=(1, 2, 3))
    for name, (n, axiom, prods) in (("fig1_25", FIG_1_25), ("fig5_5_cordate_leaf", FIG_5_5)):
        for k in steps_for(n):
            polygons.append((path(name), k) + polygon_counts(rewrite_d0l(axiom, prods, k)))
    lily = lily_rules()
    for k in steps_for(LILY_N):
        word = rewrite_param(LILY_AXIOM, lily, k)
        rows.append((path("ch5_lily_of_the_valley"), k, len(word), 0, "-"))
        polygons.append((path("ch5_lily_of_the_valley"), k) + polygon_counts(word))
        if k <= 2:
            strings.append((path("ch5_lily_of_the_valley"), k, fmt_word(word)))

    to_ramus = str.maketrans("01", "OI")
    for name, (n, axiom, succ) in FIG_1_31.items():
        table, other = hogeweg(succ), {"+": "-", "-": "+"}
        for k in [n] + sorted(set(steps_for(n) + [10, 20]) - {n}):
            word = rewrite_2l(axiom, table, other, "+-F", k)
            rows.append((path(name), k, len(word), word.count("F"), "-"))
            if len(word) <= 200:
                strings.append((path(name), k, word.translate(to_ramus)))

    rules = p42_rules()
    for k in [5, 0, 1, 2, 3, 4]:
        word = rewrite_param(P42_AXIOM, rules, k)
        length, fcount, _ = param_stats(word)
        rows.append((path("param_p42"), k, length, fcount, "-"))
    for k in range(6):
        word = rewrite_param(P42_AXIOM, rules, k)
        strings.append((path("param_p42"), k, fmt_word(word)))
        book = P42_BOOK[k].replace("1.142857", f"{8 / 7:.6f}")
        mine = fmt_word([(s, tuple(round(p, 6) for p in q)) for s, q in word])
        if mine != book:
            sys.exit(f"p42 step {k}: {mine} != book {book}")

    for name, (r1, r2, a0, a2) in FIG_2_6.items():
        rules = monopodial_rules(r1, r2, a0, a2)
        for k in steps_for(10):
            word = rewrite_param([m("A", 1, MONOPODIAL_W0)], rules, k)
            length, fcount, fsum = param_stats(word)
            rl, rf, rs = monopodial_recurrence(r1, r2, k)
            if (rl, rf) != (length, fcount) or not close(rs, fsum):
                sys.exit(f"{name} n={k}: rewriting and recurrence disagree")
            rows.append((path(name), k, length, fcount, repr(fsum)))

    for name, (d1, d2, a, lr, n) in FIG_2_8.items():
        rules = ternary_rules(d1, d2, a, lr)
        for k in steps_for(n):
            word = rewrite_param(TERNARY_AXIOM, rules, k)
            length, fcount, fsum = param_stats(word)
            cl, cf, cs = ternary_closed_form(lr, k)
            if (cl, cf) != (length, fcount) or not close(cs, fsum):
                sys.exit(f"{name} n={k}: rewriting and closed form disagree")
            rows.append((path(name), k, length, fcount, repr(fsum)))

    check_stochastic_invariant()
    rows.append((path("fig1_27"), 5, "(5*F-3)/2", "-", "-"))
    return rows, strings, polygons


def check_stochastic_invariant():
    alts = ["F[+F]F[-F]F", "F[+F]F", "F[-F]F"]
    rng = random.Random(127)
    for _ in range(200):
        word = "F"
        for _ in range(rng.randint(0, 6)):
            word = "".join(rng.choices(alts, [0.33, 0.33, 0.34])[0] if c == "F" else c
                           for c in word)
            if 2 * len(word) != 5 * word.count("F") - 3:
                sys.exit("fig. 1.27 invariant does not hold")


HEADER = """\
# Expected derivation statistics of examples/abop/, written by tests/tools/abop_oracle.py
# (an independent rewriter and Parikh/recurrence/closed-form check; see its header).
# Columns: file, steps, length, count of F, sum of F lengths ('-' when F has no parameter).
# The first row of each file is at the file's own `derive N`. A length of (5*F-3)/2 is the
# invariant of the stochastic fig. 1.27, checked for several seeds.
"""
STRINGS_HEADER = """\
# Whole derived words (ABOP notation, modules without spaces) of short derivations of
# examples/abop/, written by tests/tools/abop_oracle.py. Columns: file, steps, word.
"""


POLYGONS_HEADER = """\
# Polygon symbols of derivations of examples/abop/ (ABOP 5.2), written by
# tests/tools/abop_oracle.py. Columns: file, steps, count of '{', of '.', of '}', of G.
"""


def main():
    rows, strings, polygons = collect()
    out = os.path.join(ROOT, "tests", "expected")
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "abop.tsv"), "w") as f:
        f.write(HEADER)
        for r in rows:
            f.write("\t".join(str(x) for x in r) + "\n")
    with open(os.path.join(out, "abop_strings.tsv"), "w") as f:
        f.write(STRINGS_HEADER)
        for r in strings:
            f.write("\t".join(str(x) for x in r) + "\n")
    with open(os.path.join(out, "abop_polygons.tsv"), "w") as f:
        f.write(POLYGONS_HEADER)
        for r in polygons:
            f.write("\t".join(str(x) for x in r) + "\n")
    print(f"wrote {len(rows)} rows, {len(strings)} words and {len(polygons)} polygon counts to {out}")


if __name__ == "__main__":
    main()
