# docs/loglog.awk: a log-log plot as hand-written SVG, for docs/make-figures.sh.
#   awk -f loglog.awk DATA > plot.svg
# DATA: one point a line, "x y" (both > 0; lines starting with # are skipped).
# Draws the points joined by a line, the least-squares line through
# (log x, log y) dashed, decade grid lines, and the fitted slope.
function lg(v) { return log(v) / log(10) }
function px(v) { return L + (lg(v) - x0) / (x1 - x0) * (W - L - R) }
function py(v) { return T + (y1 - lg(v)) / (y1 - y0) * (H - T - B) }
function f(v) { return sprintf("%.2f", v) }
function floor_(v) { return v == int(v) ? v : (v < 0 ? int(v) - 1 : int(v)) }
function ceil_(v) { return v == int(v) ? v : (v > 0 ? int(v) + 1 : int(v)) }
function decade(e) { return "10<tspan dy=\"-6\" font-size=\"10\">" e "</tspan>" }
/^#/ || NF < 2 { next }
{ n++; X[n] = $1; Y[n] = $2 }
END {
    W = 640; H = 460; L = 80; R = 30; T = 50; B = 64
    for (i = 1; i <= n; i++) {
        lx = lg(X[i]); ly = lg(Y[i])
        if (i == 1 || lx < x0) x0 = lx; if (i == 1 || lx > x1) x1 = lx
        if (i == 1 || ly < y0) y0 = ly; if (i == 1 || ly > y1) y1 = ly
        sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly
    }
    slope = (n * sxy - sx * sy) / (n * sxx - sx * sx)
    icept = (sy - slope * sx) / n
    x0 = floor_(x0); x1 = ceil_(x1); y0 = floor_(y0); y1 = ceil_(y1)
    print "<?xml version=\"1.0\" encoding=\"UTF-8\"?>"
    printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\" font-family=\"sans-serif\" font-size=\"12\">\n", W, H, W, H
    print "<title>Li-Hao Fig. 5: the Euler error against the step</title>"
    printf "<rect width=\"%d\" height=\"%d\" fill=\"#ffffff\"/>\n", W, H
    print "<text x=\"12\" y=\"24\" font-size=\"15\">Li-Hao Fig. 5: Euler error against step (cubic path of Fig. 3d)</text>"
    print "<g stroke=\"#dddddd\" stroke-width=\"1\">"
    for (e = x0; e <= x1; e++)
        printf "<line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\"/>\n", f(px(10 ^ e)), f(T), f(px(10 ^ e)), f(H - B)
    for (e = y0; e <= y1; e++)
        printf "<line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\"/>\n", f(L), f(py(10 ^ e)), f(W - R), f(py(10 ^ e))
    print "</g>"
    printf "<rect x=\"%s\" y=\"%s\" width=\"%s\" height=\"%s\" fill=\"none\" stroke=\"#555555\"/>\n", f(L), f(T), f(W - L - R), f(H - T - B)
    for (e = x0; e <= x1; e++)
        printf "<text text-anchor=\"middle\" x=\"%s\" y=\"%s\">%s</text>\n", f(px(10 ^ e)), f(H - B + 20), decade(e)
    for (e = y0; e <= y1; e++)
        printf "<text text-anchor=\"end\" x=\"%s\" y=\"%s\">%s</text>\n", f(L - 8), f(py(10 ^ e) + 4), decade(e)
    printf "<text text-anchor=\"middle\" x=\"%s\" y=\"%s\">step H (in u, the fraction of a segment)</text>\n", f((L + W - R) / 2), f(H - 18)
    printf "<text text-anchor=\"middle\" transform=\"translate(22 %s) rotate(-90)\">largest error of a matrix entry</text>\n", f((T + H - B) / 2)
    printf "<polyline fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"2\" points=\""
    for (i = 1; i <= n; i++) printf "%s%s,%s", (i > 1 ? " " : ""), f(px(X[i])), f(py(Y[i]))
    print "\"/>"
    for (i = 1; i <= n; i++)
        printf "<circle cx=\"%s\" cy=\"%s\" r=\"3.5\" fill=\"#1f77b4\"/>\n", f(px(X[i])), f(py(Y[i]))
    # the fitted line, across the data's range
    xa = lg(X[1]); xb = xa
    for (i = 2; i <= n; i++) { if (lg(X[i]) < xa) xa = lg(X[i]); if (lg(X[i]) > xb) xb = lg(X[i]) }
    printf "<line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\" stroke=\"#d62728\" stroke-width=\"1.5\" stroke-dasharray=\"7 5\"/>\n", f(px(10 ^ xa)), f(py(10 ^ (icept + slope * xa))), f(px(10 ^ xb)), f(py(10 ^ (icept + slope * xb)))
    printf "<line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\" stroke=\"#1f77b4\" stroke-width=\"2\"/>\n", f(L + 14), f(T + 20), f(L + 36), f(T + 20)
    printf "<text x=\"%s\" y=\"%s\">measured: --eval euler --step H against --eval direct</text>\n", f(L + 42), f(T + 24)
    printf "<line x1=\"%s\" y1=\"%s\" x2=\"%s\" y2=\"%s\" stroke=\"#d62728\" stroke-width=\"1.5\" stroke-dasharray=\"7 5\"/>\n", f(L + 14), f(T + 40), f(L + 36), f(T + 40)
    printf "<text x=\"%s\" y=\"%s\">least-squares fit: slope %.3f</text>\n", f(L + 42), f(T + 44), slope
    print "</svg>"
}
