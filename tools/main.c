/* tools/main.c: the garotor command line: dispatch, options, help.
 * The reference for every command and option is docs/tool.md. */
#include "cli.h"
#include "eval.h"

#include <garotor/version.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

typedef struct {
    const char *name;
    int (*run)(const cli_opts *o);
    opt_bits accepts; /* OPT_* bits */
    const char *help;
    const char *help_more; /* the help's rest, NULL for none (a string literal has at most 4095 bytes) */
} command;

static const command commands[] = {
    {"demo", cmd_demo, OPT_SVG | OPT_VIEW | OPT_HTML,
     "usage: garotor [demo] [--svg FILE [--view iso|xy|xz|yz]] [--html FILE]\n"
     "Run the built-in demonstration and print a short report: three key poses,\n"
     "the screw between consecutive keys, samples of the screw and quadratic\n"
     "paths through them, and how far rotors and 4x4 matrices disagree.\n"
     "  --svg FILE       also draw the two paths as an SVG picture\n"
     "  --view V         the picture's view: iso (default), xy, xz or yz\n"
     "  --html FILE      also write a web page that draws them in 3D (drag to turn)\n",
     NULL},
    {"exp", cmd_exp, OPT_IN | OPT_OUT | OPT_HEADER | OPT_GROUP | OPT_MAX_LINE,
     "usage: garotor exp [--group cga|matrix|affine] [--in FILE] [--out FILE] [--header]\n"
     "                   [--max-line N]\n"
     "Read one twist a line (wx wy wz vx vy vz) and write its motion, the 4x4\n"
     "matrix expm([[w]x, v; 0, 0]) (16 numbers, row-major).\n"
     "  --group cga      through the rotor exp(B(xi)) (Wareham-Lasenby Thm 3; default)\n"
     "  --group matrix   through Eberly's SE(3) closed form\n"
     "  --group affine   items are 4x4 matrices with last row zero, general matrix exp\n"
     "  --in FILE, --out FILE   input and output (default standard input and output)\n"
     "  --header         skip the first line of the input (a CSV header)\n"
     "  --max-line N     a line of more than N bytes is an error (default 1048576)\n",
     NULL},
    {"log", cmd_log, OPT_IN | OPT_OUT | OPT_HEADER | OPT_GROUP | OPT_MAX_LINE,
     "usage: garotor log [--group cga|matrix|affine] [--in FILE] [--out FILE] [--header]\n"
     "                   [--max-line N]\n"
     "Read one rigid motion a line (a 4x4 matrix, 16 numbers, row-major) and write\n"
     "its principal twist (6 numbers; rotation angle in [0, pi]).\n"
     "  --group cga      through the rotor logarithm l(R) (Wareham-Lasenby Thm 9; default)\n"
     "  --group matrix   through Eberly's SE(3) closed form\n"
     "  --group affine   any 4x4 with last row 0 0 0 1 and det > 0; writes the\n"
     "                   principal matrix log as a 4x4 with last row zero\n"
     "  --in FILE, --out FILE, --header, --max-line N   as for exp\n",
     NULL},
    {"interp", cmd_interp,
     OPT_IN | OPT_OUT | OPT_HEADER | OPT_GROUP | OPT_SCHEME | OPT_SAMPLES | OPT_AT | OPT_FORMAT | OPT_EVAL |
         OPT_STEP | OPT_V0 | OPT_VELOCITIES | OPT_SVG | OPT_VIEW | OPT_NORMALIZE | OPT_WITH | OPT_FRAME |
         OPT_RATE | OPT_TIMES | OPT_EXTRAPOLATE | OPT_HTML | OPT_TIME_UNIT | OPT_MAX_LINE | OPT_CLIP |
         OPT_QUAT_ORDER | OPT_OUTPUT_FORMAT | OPT_TWIST_ORDER | OPT_COLUMNS | OPT_MIN_GAP | OPT_DEDUP |
         OPT_STAMPS,
     "usage: garotor interp [--scheme S] (--samples N | --at T1,T2,... | --rate HZ |\n"
     "                      --times FILE) [OPTIONS]\n"
     "Read keyframes, one a line: t, then the pose (t strictly increasing), and\n"
     "write samples of the path through them in the same format. One key is the\n"
     "constant path.\n"
     "  --scheme screw      piecewise screw-linear (default)\n"
     "  --scheme bivector   piecewise-linear in the generators l(R_i)\n"
     "  --scheme quadratic  exactly 3 keys: quadratic in the generators\n"
     "  --scheme smooth     n >= 3 keys: C1 piecewise-quadratic in the generators\n"
     "  --scheme lihao2     Li-Hao C1 quadratic form; --v0 W1 W2 W3 V1 V2 V3 gives\n"
     "                      the body velocity at the first key\n"
     "  --scheme lihao3     Li-Hao cubic form; --velocities FILE gives one body\n"
     "                      velocity (6 numbers, per unit t) per key\n"
     "  --scheme decoupled  position linear, rotation by slerp (cga, matrix)\n"
     "  --scheme decoupled-c2   position by the not-a-knot cubic spline, rotation\n"
     "                      by a C2 cubic in the rotation vector (cga, matrix)\n",
     "  --scheme bspline    n >= 4 evenly spaced keys as control poses of the\n"
     "                      uniform cumulative cubic B-spline (C2; the keys are not\n"
     "                      hit), defined from the second key's t to the last but one's\n"
     "  --scheme c2         C2 through every key from screw motions: a cubic in the\n"
     "                      twist on each segment (cga, matrix)\n"
     "  --samples N         N >= 2 samples from the first key's t to the last's\n"
     "                      (bspline: over its range)\n"
     "  --at T1,T2,...      samples at these times instead\n"
     "  --rate HZ           samples at t0 + k/HZ, k = 0, 1, ... up to the last key\n"
     "                      (bspline: those in its range)\n"
     "  --times FILE        samples at the times in FILE, one a line\n"
     "  --extrapolate error|hold|extend|constant-velocity   a sample time outside the\n"
     "                      keys: an error (default), the end key with zero velocity,\n"
     "                      the end segment's formula continued, or the end pose\n"
     "                      moved on by its velocity there (bspline: outside its\n"
     "                      range; hold gives the range's end pose)\n"
     "  --clip              drop the --at and --times outside the keys instead\n"
     "  --min-gap DT        keys closer than DT (in the keys' unit; default 1% of\n"
     "                      their median spacing, 0: none) are an error, or with\n"
     "  --dedup             merged: one key at their mean time and mean pose\n"
     "  --time-unit s|ns    times in seconds or whole nanoseconds; read exactly from\n"
     "                      their text, and a sample at a key's time is stamped as\n"
     "                      the key was (velocities: per second). Without it, whole\n"
     "                      numbers of 12 digits or more are an error (ms, us, ns?)\n"
     "  --format mat|pose|kitti   a key is t and 16 numbers (4x4, default), t x y z\n"
     "                      qx qy qz qw, or 12 numbers (KITTI's 3x4, key k at t = k)\n"
     "  --stamps FILE       kitti: key k at the k-th time of FILE (times.txt)\n"
     "  --quat-order xyzw|wxyz   the quaternion's order in a pose (default xyzw)\n"
     "  --columns LIST      pose keys in any layout: the file's columns in order\n"
     "                      (t,x,y,z,qw,qx,qy,qz; - skips one), or ROLE=COLUMN pairs\n"
     "                      (a number from 1 or a header name), and header: the\n"
     "                      first line names the columns, found by name\n"
     "  --output-format mat|pose|tum|kitti|csv   what a sample's line is: as the\n"
     "                      keys (default), t x y z qx qy qz qw (tum: always xyzw),\n"
     "                      the 3x4 without t, or pose columns with commas and a header\n"
     "  --twist-order wv|vw   a velocity's order, written and read: w v (default) or\n"
     "                      v w (ROS's Twist: linear, then angular)\n"
     "  --group cga|matrix|affine   rotors (default), SE(3) matrices, or general\n"
     "                      homogeneous matrices (keys in --format mat)\n"
     "  --eval direct|exact|euler   closed form (default), exact incremental\n"
     "                      stepping, or Li-Hao's generalized Euler (needs --step H)\n"
     "  --step H            the Euler step, in units of u (segment fraction)\n"
     "  --normalize         accept key rotations up to 1e-3 off (quaternion norm,\n"
     "                      max |R^T R - I|) and project them onto the group\n"
     "  --with velocity,acceleration,jerk   append to each sample those listed, in\n"
     "                      that order: its velocity (w v, per unit t), its\n"
     "                      acceleration (per unit t^2), its jerk (per unit t^3)\n"
     "  --frame body|spatial|world   those of the body twist (default), the spatial\n"
     "                      twist, or world: w in world axes and the derivatives\n"
     "                      of the position\n"
     "  --svg FILE          also draw the path: the trajectory of the origin, frames\n"
     "                      at the keys and along it, the screw axis if it is one\n"
     "  --view V            the picture's view: iso (default), xy, xz or yz\n"
     "  --html FILE         also write a web page that draws the path in 3D (drag to turn)\n"
     "  --in FILE, --out FILE, --header, --max-line N   as for exp (--max-line also\n"
     "                      for --times and --velocities)\n"},
    {"versor", cmd_versor, OPT_VERB | OPT_IN | OPT_OUT | OPT_HEADER | OPT_MAX_LINE | OPT_TEXT,
     "usage: garotor versor exp|log|apply [--text] [--in FILE] [--out FILE] [--header]\n"
     "                      [--max-line N]\n"
     "The general algebra of G(4,1), one item a line (docs/versors.md).\n"
     "  exp      a bivector, 10 numbers: the coefficients of\n"
     "           e12 e13 e14 e15 e23 e24 e25 e34 e35 e45; writes exp(B), 32 numbers\n"
     "           in canonical order (1; e1..e5; e12..e45; e123..e345; e1234..e2345;\n"
     "           e12345). exp(a e45) is the dilation by e^(-2a) about the origin\n"
     "  log      a rotor (an even versor with R ~R = 1), 32 numbers; writes its\n"
     "           principal log, 10 numbers, with exp(log R) = R: log(exp(B)) = B\n"
     "           whenever every rotation part of B has half-angle below pi/2.\n"
     "           An error where R has no real logarithm (not a rotor to 1e-9)\n"
     "  apply    a versor V (32 numbers) then a point x (3 numbers); writes the\n"
     "           point whose embedding is V F(x) V^-1 (with the grade involution\n"
     "           of F(x) for odd V); an error where it goes to infinity\n"
     "  --text   multivectors in and out with blade names, 1 + 2e12 - 0.5e45, in\n"
     "           place of the numbers (docs/conventions.md); apply reads V; x y z\n"
     "  --in FILE, --out FILE, --header, --max-line N   as for exp\n",
     NULL},
    {"object", cmd_object, OPT_VERB | OPT_IN | OPT_OUT | OPT_HEADER | OPT_MAX_LINE,
     "usage: garotor object OP [--in FILE] [--out FILE] [--header] [--max-line N]\n"
     "Conformal objects, one item a line, fields separated by ';'. An object is a\n"
     "multivector with blade names (2e1235, 1 + 2e12 - 0.5e45) or one of\n"
     "  point P, pair P Q, line P Q, circle P Q S, plane P Q S, sphere P Q S U\n"
     "  (through points: three numbers each), sphere C R (centre, radius),\n"
     "  plane N D (the plane n.x = D)\n"
     "built in direct form (a vector is a point). A versor V is a multivector or\n"
     "  translation T, rotation AXIS ANGLE, dilation C F, reflection N D,\n"
     "  inversion C R, transversion T (T, AXIS, C, N: three numbers each)\n"
     "OP is one of\n"
     "  build     an object: writes it as a multivector\n"
     "  read      an object: writes its kind, reality, centre, direction, r2 and\n"
     "            the bounds err, r2_err, angle_err of ga_object_from_mv (a vector\n"
     "            is read as a dual sphere or plane: a point as a sphere of r2 0)\n"
     "  meet      A; B: the meet in the whole space (0 in special position)\n"
     "  join      A; B: the smallest object holding both\n"
     "  meet-rel  A; B: the meet relative to their join (any position)\n"
     "  move      V; X: X moved by V, V X V^-1 (exact translation for a rigid V)\n"
     "  between   A; B: a rotor taking A to B, two objects of one kind, with a\n"
     "            dilation where their sizes differ\n"
     "  interp    A; B; T: the object at T along that rotor (A at 0, B at 1)\n"
     "  --in FILE, --out FILE, --header, --max-line N   as for exp\n",
     NULL},
};

static const char usage[] = "usage: garotor [COMMAND] [OPTIONS]\n"
                            "Rigid motions in conformal geometric algebra G(4,1).\n"
                            "\n"
                            "commands:\n"
                            "  demo     (the default) the built-in demonstration\n"
                            "  exp      twists to rigid motions (4x4 matrices)\n"
                            "  log      rigid motions to their principal twists\n"
                            "  interp   sample a path through key poses\n"
                            "  versor   exp, log and action of general rotors and versors\n"
                            "  object   build, read back, meet, join and move conformal objects\n"
                            "  eval     APE and RPE of an estimated trajectory against a reference\n"
                            "  fit      least-squares B-spline through noisy poses\n"
                            "\n"
                            "garotor COMMAND --help shows a command's options;\n"
                            "garotor --version prints the version.\n"
                            "An option's value may follow it or be joined to it: --samples 5, --samples=5.\n";

static const struct {
    const char *name;
    opt_bits bit;
    int takes_value;
} option_table[] = {
    {"--in", OPT_IN, 1},
    {"--out", OPT_OUT, 1},
    {"--header", OPT_HEADER, 0},
    {"--group", OPT_GROUP, 1},
    {"--scheme", OPT_SCHEME, 1},
    {"--samples", OPT_SAMPLES, 1},
    {"--at", OPT_AT, 1},
    {"--format", OPT_FORMAT, 1},
    {"--eval", OPT_EVAL, 1},
    {"--step", OPT_STEP, 1},
    {"--v0", OPT_V0, 6},
    {"--velocities", OPT_VELOCITIES, 1},
    {"--svg", OPT_SVG, 1},
    {"--view", OPT_VIEW, 1},
    {"--normalize", OPT_NORMALIZE, 0},
    {"--with", OPT_WITH, 1},
    {"--frame", OPT_FRAME, 1},
    {"--rate", OPT_RATE, 1},
    {"--times", OPT_TIMES, 1},
    {"--extrapolate", OPT_EXTRAPOLATE, 1},
    {"--html", OPT_HTML, 1},
    {"--time-unit", OPT_TIME_UNIT, 1},
    {"--max-line", OPT_MAX_LINE, 1},
    {"--text", OPT_TEXT, 0},
    {"--clip", OPT_CLIP, 0},
    {"--quat-order", OPT_QUAT_ORDER, 1},
    {"--output-format", OPT_OUTPUT_FORMAT, 1},
    {"--twist-order", OPT_TWIST_ORDER, 1},
    {"--columns", OPT_COLUMNS, 1},
    {"--min-gap", OPT_MIN_GAP, 1},
    {"--dedup", OPT_DEDUP, 0},
    {"--stamps", OPT_STAMPS, 1},
};

/* A usage error of command cmd (NULL: the demo, no command named), with a
 * hint and its tail after the argument (or ""). */
static int usage_hint(const char *cmd, const char *what, const char *arg, const char *hint, const char *tail)
{
    if (cmd)
        fprintf(stderr, "garotor %s: %s%s%s%s%s\n(garotor %s --help shows the options)\n", cmd, what,
                arg ? ": " : "", arg ? arg : "", hint, tail, cmd);
    else
        fprintf(stderr,
                "garotor: %s%s%s%s%s\n(garotor --help shows the commands, garotor demo --help the demo's "
                "options)\n",
                what, arg ? ": " : "", arg ? arg : "", hint, tail);
    return 2;
}

static int usage_error(const char *cmd, const char *what, const char *arg)
{
    return usage_hint(cmd, what, arg, "", "");
}

/* The optimal string alignment distance of a[0..la) and b: the fewest
 * letters left out, added, changed or two neighbours swapped (99 for names
 * too long to be options). */
static int edit_distance(const char *a, size_t la, const char *b)
{
    size_t lb = strlen(b);
    int d[33][33];
    if (la > 32 || lb > 32)
        return 99;
    for (size_t i = 0; i <= la; i++) d[i][0] = (int)i;
    for (size_t j = 0; j <= lb; j++) d[0][j] = (int)j;
    for (size_t i = 1; i <= la; i++)
        for (size_t j = 1; j <= lb; j++) {
            int x = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            x = d[i - 1][j] + 1 < x ? d[i - 1][j] + 1 : x;
            x = d[i][j - 1] + 1 < x ? d[i][j - 1] + 1 : x;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] && d[i - 2][j - 2] + 1 < x)
                x = d[i - 2][j - 2] + 1;
            d[i][j] = x;
        }
    return d[la][lb];
}

/* Into hint: ": did you mean NAME?" (or "A or B?", "A, B or C?") for the
 * names nearest to word[0..len): within one edit of a name of up to four
 * letters after its dashes, two of a longer one; failing that, the names it
 * begins, three letters at least. "" when none, or more than three. */
static void did_you_mean(const char *word, size_t len, const char *const *name, int n, char *hint, size_t cap)
{
    int best = 99, pick[3], np = 0;
    for (int k = 0; k < n; k++) {
        size_t body = strlen(name[k]) - strspn(name[k], "-");
        int dk = edit_distance(word, len, name[k]);
        if (dk <= (body <= 4 ? 1 : 2) && dk < best)
            best = dk;
    }
    for (int k = 0; k < n && best < 99; k++)
        if (edit_distance(word, len, name[k]) == best && np++ < 3)
            pick[np - 1] = k;
    size_t dashes = strspn(word, "-");
    if (np == 0)
        for (int k = 0; k < n; k++)
            if (len >= dashes + 3 && strncmp(word, name[k], len) == 0 && np++ < 3)
                pick[np - 1] = k;
    hint[0] = '\0';
    if (np == 0 || np > 3)
        return;
    size_t at = (size_t)snprintf(hint, cap, ": did you mean ");
    for (int k = 0; k < np && at < cap; k++)
        at += (size_t)snprintf(hint + at, cap - at, "%s%s", name[pick[k]],
                               k + 2 < np    ? ", "
                               : k + 2 == np ? " or "
                                             : "?");
}

static int parse_double(const char *s, double *out)
{
    char *end;
    errno = 0;
    double x = strtod(s, &end);
    if (end == s || *end != '\0' || !isfinite(x))
        return -1;
    *out = x;
    return 0;
}

#define NOPT (sizeof option_table / sizeof option_table[0])
#define NCMD (sizeof commands / sizeof commands[0])

/* argv[i], no option of command c (cmd: its name in messages, NULL for the
 * demo named by no command): the message says what was probably meant. A
 * word that names a file, or does not start with '-', is the input without
 * --in; an option a letter or two off one of c's is misspelt (--version and
 * --help included, where they are taken); an option of another command is
 * named as such. */
static int unknown_option(const command *c, const char *cmd, int argc, char **argv, int i, size_t len)
{
    const char *a = argv[i];
    struct stat st;
    int in_given = 0;
    for (int j = 0; j < argc; j++)
        in_given |= strcmp(argv[j], "--in") == 0 || strncmp(argv[j], "--in=", 5) == 0;
    if ((c->accepts & OPT_IN) && !in_given && (a[0] != '-' || stat(a, &st) == 0))
        return usage_hint(cmd, "unknown option", a, ": a file to read? pass --in ", a);
    const char *name[NOPT + 2];
    int n = 0;
    for (size_t k = 0; k < NOPT; k++)
        if (c->accepts & option_table[k].bit)
            name[n++] = option_table[k].name;
    name[n++] = "--help";
    if (!cmd && i == 0) /* garotor --version, only there */
        name[n++] = "--version";
    char hint[160];
    did_you_mean(a, len, name, n, hint, sizeof hint);
    for (size_t k = 0; k < NOPT && !hint[0]; k++) {
        if (strncmp(a, option_table[k].name, len) != 0 || option_table[k].name[len] != '\0')
            continue;
        /* another command's option: which ones take it */
        size_t at = (size_t)snprintf(hint, sizeof hint, ": an option of garotor ");
        int m = 0, total = 0;
        for (size_t j = 0; j < NCMD; j++) total += (commands[j].accepts & option_table[k].bit) != 0;
        for (size_t j = 0; j < NCMD && at < sizeof hint; j++)
            if (commands[j].accepts & option_table[k].bit) {
                m++;
                at += (size_t)snprintf(hint + at, sizeof hint - at, "%s%s", commands[j].name,
                                       m + 1 < total    ? ", "
                                       : m + 1 == total ? " and "
                                                        : "");
            }
        if (at < sizeof hint)
            snprintf(hint + at, sizeof hint - at, cmd ? ", not of %s" : ": name the command first",
                     cmd ? cmd : "");
    }
    return usage_hint(cmd, "unknown option", a, hint, "");
}

/* --name VALUE or --name=VALUE (a one-value option only); an option given
 * twice is an error rather than a silent choice of one of the two. cmd: the
 * command's name in messages (NULL: the demo, no command named). */
static int parse_options(const command *c, const char *cmd, int argc, char **argv, cli_opts *o)
{
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *eq = strchr(a, '=');
        size_t len = (a[0] == '-' && eq) ? (size_t)(eq - a) : strlen(a);
        size_t k = 0;
        while (k < NOPT && !(strncmp(a, option_table[k].name, len) == 0 && option_table[k].name[len] == '\0'))
            k++;
        if (k == NOPT || !(c->accepts & option_table[k].bit))
            return unknown_option(c, cmd, argc, argv, i, len);
        if (a[len] == '=' && option_table[k].takes_value != 1)
            return usage_error(cmd,
                               option_table[k].takes_value
                                   ? "--v0 takes its six numbers as separate words, not"
                                   : "this option takes no value",
                               a);
        if (o->given & option_table[k].bit)
            return usage_error(cmd, "option given twice", option_table[k].name);
        const char *v;
        if (a[len] == '=') {
            v = a + len + 1;
        } else {
            if (i + option_table[k].takes_value >= argc)
                return usage_error(cmd, "missing value for", a);
            v = argv[i + 1];
            i += option_table[k].takes_value;
        }
        o->given |= option_table[k].bit;
        switch (option_table[k].bit) {
        case OPT_IN: o->in = v; break;
        case OPT_OUT: o->out = v; break;
        case OPT_HEADER: o->header = 1; break;
        case OPT_GROUP: o->group = v; break;
        case OPT_SCHEME: o->scheme = v; break;
        case OPT_FORMAT: o->format = v; break;
        case OPT_EVAL: o->eval = v; break;
        case OPT_AT: o->at = v; break;
        case OPT_VELOCITIES: o->velocities = v; break;
        case OPT_SVG: o->svg = v; break;
        case OPT_HTML: o->html = v; break;
        case OPT_VIEW: o->view = v; break;
        case OPT_NORMALIZE: o->normalize = 1; break;
        case OPT_TEXT: o->text = 1; break;
        case OPT_WITH: o->with = v; break;
        case OPT_FRAME: o->frame = v; break;
        case OPT_TIMES: o->times = v; break;
        case OPT_EXTRAPOLATE: o->extrapolate = v; break;
        case OPT_TIME_UNIT: o->time_unit = v; break;
        case OPT_CLIP: o->clip = 1; break;
        case OPT_QUAT_ORDER: o->quat_order = v; break;
        case OPT_OUTPUT_FORMAT: o->output_format = v; break;
        case OPT_TWIST_ORDER: o->twist_order = v; break;
        case OPT_COLUMNS: o->columns = v; break;
        case OPT_STAMPS: o->stamps = v; break;
        case OPT_DEDUP: o->dedup = 1; break;
        case OPT_MIN_GAP:
            if (parse_double(v, &o->min_gap) || !(o->min_gap >= 0.0))
                return usage_error(cmd, "--min-gap needs a number >= 0, not", v);
            break;
        case OPT_MAX_LINE: {
            char *end = NULL;
            errno = 0;
            unsigned long long x = v[0] >= '0' && v[0] <= '9' ? strtoull(v, &end, 10) : 0;
            if (!end || *end || errno || x < 1 || x > TIO_MAX_LINE_MAX)
                return usage_error(cmd, "--max-line needs a whole number of bytes >= 1, not", v);
            o->max_line = (size_t)x;
            break;
        }
        case OPT_RATE:
            if (parse_double(v, &o->rate) || !(o->rate > 0.0))
                return usage_error(cmd, "--rate needs a number > 0, not", v);
            o->rate_text = v;
            break;
        case OPT_SAMPLES: {
            char *end;
            errno = 0;
            o->samples = strtol(v, &end, 10);
            if (end == v || *end || errno || o->samples < 2)
                return usage_error(cmd, "--samples needs a whole number >= 2, not", v);
            break;
        }
        case OPT_STEP:
            if (parse_double(v, &o->step) || !(o->step >= 1e-9 && o->step <= 1.0)) /* path.h */
                return usage_error(cmd, "--step needs a number in [1e-9, 1] (u units), not", v);
            break;
        case OPT_V0:
            for (int j = 0; j < 6; j++)
                if (parse_double(argv[i - 5 + j], &o->v0[j]))
                    return usage_error(cmd, "--v0 needs 6 finite numbers, not", argv[i - 5 + j]);
            break;
        }
    }
    return 0;
}

/* The exit status, once standard output is flushed: whatever went there
 * (the demo's report, --help, --version, a command's results) must have
 * reached it, else the status is 2. */
static int flushed(int rc)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        if (rc == 0) /* a command that failed to write has said so */
            fprintf(stderr, "garotor: <stdout>: write error\n");
        return 2;
    }
    return rc;
}

/* argv[1], no command: the command meant, or the input named without one. */
static int unknown_command(const char *word)
{
    const char *name[NCMD + 2];
    char hint[160];
    struct stat st;
    for (size_t k = 0; k < NCMD; k++) name[k] = commands[k].name;
    name[NCMD] = "eval", name[NCMD + 1] = "fit"; /* dispatched before the table */
    did_you_mean(word, strlen(word), name, (int)NCMD + 2, hint, sizeof hint);
    if (!hint[0] && stat(word, &st) == 0)
        fprintf(stderr,
                "garotor: unknown command '%s': a file to read? name the command first: garotor "
                "COMMAND --in %s\n%s",
                word, word, usage);
    else
        fprintf(stderr, "garotor: unknown command '%s'%s\n%s", word, hint, usage);
    return 2;
}

int main(int argc, char **argv)
{
    const command *c = &commands[0]; /* no arguments: the demonstration */
    int first = 1;
    if (argc > 1 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        fputs(usage, stdout);
        return flushed(0);
    }
    if (argc > 1 && strcmp(argv[1], "--version") == 0) {
        printf("garotor %s\n", GAROTOR_VERSION_STRING);
        return flushed(0);
    }
    if (argc > 1 && strcmp(argv[1], "eval") == 0) /* its own options: tools/cmd_eval.c */
        return flushed(cmd_eval_main(argc - 2, argv + 2));
    if (argc > 1 && strcmp(argv[1], "fit") == 0) /* its own options: tools/cmd_fit.c */
        return flushed(cmd_fit_main(argc - 2, argv + 2));
    if (argc > 1 && argv[1][0] != '-') {
        size_t k = 0;
        while (k < NCMD && strcmp(argv[1], commands[k].name) != 0) k++;
        if (k == NCMD)
            return unknown_command(argv[1]);
        c = &commands[k];
        first = 2;
    }
    for (int i = first; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(c->help, stdout);
            if (c->help_more)
                fputs(c->help_more, stdout);
            return flushed(0);
        }
    cli_opts o;
    memset(&o, 0, sizeof o);
    if ((c->accepts & OPT_VERB) && first < argc && argv[first][0] != '-')
        o.verb = argv[first++];
    int st = parse_options(c, first == 1 ? NULL : c->name, argc - first, argv + first, &o);
    return flushed(st ? st : c->run(&o));
}
