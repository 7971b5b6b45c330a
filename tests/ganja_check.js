// tests/ganja_check.js: recompute tests/ganja_dump.c's cases with ganja.js
// (Algebra(4,1) in Float64) and compare, per operation. Reads the dump on
// standard input; prints the worst difference per operation; exits 1 when
// one exceeds its bound.
//
//   node tests/ganja_check.js GANJA_MODULE_DIR < dump
//
// garotor's names against ganja's (docs/conventions.md, "Products"): gp is
// Mul, op Wedge, lc LDot, dot Dot (`|`), reverse Reverse, involute Involute,
// conjugate Conjugate; ga_mv_dual (X I^-1) is ganja's UnDual and
// ga_mv_undual (X I) its Dual; the sandwich of V is V X V.Inverse, with
// X.Involute for odd V. The basis orders are the same (ganja's describe()
// is checked against garotor's canonical order first).
//
// Bounds. Products: each coefficient is a sum of at most 32 products of
// coefficients in [-1, 1], summed in some order: two orders differ by at
// most 32 * 2u per unit of sum(|terms|) <= 32, so 2048 u = 2.3e-13 (u = 2^-53)
// absolute. Involutions and duals move or negate coefficients: exact.
// Sandwich: V X V^-1 with V a product of up to 4 vectors of squares >= 0.1
// in size: the two products and the inverse each add a relative 2048 u of
// |V| |X| |V^-1| (32^2 terms a coefficient), so the bound is 3 * 2048 u
// times 32 |V| 32 |X| |V^-1| (max norms), relative to that scale.
// vee (ganja's Vee, garotor's ga_mv_regressive) is an outer product between
// moves and sign changes of coefficients: the products' bound. Inverse of a
// dense a (ganja's Inverse, Hitzer and Sangwine's closed form as
// garotor's): garotor's X is within u |a|_1 |X|_1^2 of a^-1 (mv.h: its
// residual within u |a|_1 |X|_1, 2u here, times |a^-1|_1); the closed form
// without garotor's Newton step leaves a residual some hundred times that
// (its five products, each rounded at 32 u of sums of the sizes), so the
// two agree to 512 u of |a|_1 |X|_1^2.
"use strict";
const path = require("path");
const Algebra = require(process.argv[2] ? path.resolve(process.argv[2]) : "ganja.js");
const A = Algebra({p: 4, q: 1, baseType: Float64Array});
const canonical = ["1", "e1", "e2", "e3", "e4", "e5", "e12", "e13", "e14", "e15", "e23", "e24", "e25", "e34",
    "e35", "e45", "e123", "e124", "e125", "e134", "e135", "e145", "e234", "e235", "e245", "e345", "e1234",
    "e1235", "e1245", "e1345", "e2345", "e12345"];
const basis = A.describe().basis.map(String);
if (basis.join(" ") !== canonical.join(" ")) {
    console.log("FAIL ganja's basis order differs: " + basis.join(" "));
    process.exit(1);
}
const u = 2 ** -53;
const el = (xs) => { const e = new A(); for (let i = 0; i < 32; i++) e[i] = xs[i]; return e; };
const maxabs = (x) => { let m = 0; for (let i = 0; i < 32; i++) m = Math.max(m, Math.abs(x[i])); return m; };
const unary = {reverse: (a) => a.Reverse, involute: (a) => a.Involute, conjugate: (a) => a.Conjugate,
    dual: (a) => a.UnDual, undual: (a) => a.Dual};
const binary = {gp: (a, b) => A.Mul(a, b), op: (a, b) => A.Wedge(a, b), lc: (a, b) => A.LDot(a, b),
    dot: (a, b) => A.Dot(a, b), vee: (a, b) => A.Vee(a, b)};
const sumabs = (x) => { let s = 0; for (let i = 0; i < 32; i++) s += Math.abs(x[i]); return s; };
const worst = {}, count = {}, bound = {};
let bad = 0;
const lines = require("fs").readFileSync(0, "utf8").split("\n");
for (const line of lines) {
    if (!line) continue;
    const f = line.split(" "), op = f[0], v = f.slice(1).map(Number);
    const m = (k) => el(v.slice(32 * k, 32 * k + 32));
    let want, got, scale, tol;
    if (op in unary) {
        got = m(1); want = unary[op](m(0)); scale = 1; tol = 0;
    } else if (op in binary) {
        got = m(2); want = binary[op](m(0), m(1)); scale = 1; tol = 2048 * u;
    } else if (op === "inverse") {
        got = m(1); want = m(0).Inverse;
        scale = sumabs(m(0)) * sumabs(got) * sumabs(got); tol = 512 * u;
    } else if (op === "sandwich") {
        const V = m(0), X = m(1), Vi = V.Inverse;
        let odd = false;
        for (let i = 0; i < 32; i++) if (V[i] !== 0 && basis[i].length % 2 === 0) odd = true; // e1: 2 chars
        got = m(2); want = A.Mul(A.Mul(V, odd ? X.Involute : X), Vi);
        scale = 32 * maxabs(V) * 32 * maxabs(X) * maxabs(Vi); tol = 3 * 2048 * u;
    } else {
        console.log("FAIL unknown operation in the dump: " + op);
        process.exit(1);
    }
    let d = 0;
    for (let i = 0; i < 32; i++) d = Math.max(d, Math.abs(want[i] - got[i]));
    d /= scale;
    if (!(d <= tol)) bad++;
    worst[op] = Math.max(worst[op] || 0, d);
    if (Number.isNaN(d)) worst[op] = NaN;
    count[op] = (count[op] || 0) + 1;
    bound[op] = tol;
}
for (const op of Object.keys(count)) {
    const ok = worst[op] <= bound[op];
    console.log((ok ? "ok   " : "FAIL ") + op.padEnd(10) + " n=" + String(count[op]).padEnd(6) + " worst " +
        worst[op].toExponential(3) + "  bound " + bound[op].toExponential(1) +
        (op === "sandwich" ? " (relative to 32|V| 32|X| |V^-1|)" : "") +
        (op === "inverse" ? " (relative to |a|_1 |a^-1|_1^2)" : ""));
}
if (Object.keys(count).length !== 12) { console.log("FAIL expected 12 operations in the dump"); bad++; }
process.exit(bad ? 1 : 0);
