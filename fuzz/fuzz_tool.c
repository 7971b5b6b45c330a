/* fuzz/fuzz_tool.c: libFuzzer target for the garotor tool, end to end.
 *
 * The tool's main() is compiled in as garotor_main (fuzz/meson.build builds
 * tools/main.c with -Dmain=garotor_main), so option parsing, every input
 * format and the output files are all exercised as a user meets them.
 *
 * Input (text, so the seed corpus in fuzz/corpus/tool/ reads as examples):
 *
 *     line 1     the command line after "garotor": a command (exp, log,
 *                interp, versor exp|log|apply) and its options, e.g.
 *                "interp --scheme lihao3 --format pose --samples 5"
 *     the rest   the input file (twists, matrices, keyframes, CSV...); a line
 *                "%%" splits off a velocity file (for --velocities)
 *
 * The target removes --in, --out, --svg and --velocities with their values
 * from line 1 and adds its own files in a private temporary directory
 * (--velocities and --svg only when line 1 asked for them). Resource limits,
 * so that a run measures correctness and not patience: --samples is capped at
 * 4096, --rate is lowered to give at most 4096 samples over the span of the
 * input's first numbers (the tool streams its samples in constant memory,
 * but the time of a run and of reading its output back grows with them, and
 * --svg holds them), and an Euler --step below 1e-3 is raised to 1e-3
 * (all legal and merely slow or large); "demo" and --help (anywhere) are skipped.
 * --max-line passes through: the seeds give small ones, so that lines longer
 * than the limit cost nothing, and the input's bytes are fed as they are, NUL
 * bytes included. The tool reads its input a few bytes at a time here
 * (tio_read_block, 1 to 61 bytes, from the input's size), so that short
 * inputs cross reads as a long file crosses the tool's 65536-byte ones.
 *
 * Invariants (docs/tool.md, docs/errors.md), besides "no crash, no sanitizer
 * report, no leak":
 *   - the exit status is 0 or 2;
 *   - status 0 only if no file the tool read (the input, a velocity file)
 *     has a NUL byte or a line longer than --max-line (default 1048576);
 *   - status 2 leaves no output file, no picture and no temporary file;
 *   - status 0 leaves the output file, every number in it finite, lines of
 *     one width (6 or 16 numbers; for interp 8, 12 (kitti) or 17, plus 6,
 *     12, 18, 16, 32 or 48 with --with velocity,acceleration,jerk; csv after
 *     its header line, its commas read as blanks); versor --text writes
 *     blade names, not checked as numbers;
 *   - exp (cga, matrix) writes rigid motions: last row exactly 0 0 0 1,
 *     rotation part orthonormal to 1e-9; log (cga, matrix) writes twists with
 *     rotation angle in [0, pi]; interp --format mat on cga/matrix writes
 *     rigid motions, --format pose unit quaternions (to 1e-9);
 *   - versor exp writes 32 numbers, an even multivector with R ~R = 1 to
 *     1e-9 |R|^2; versor log writes 10 numbers (a bivector) whose exp is the
 *     line read, to 1e-9 |R| (ga_mv_log's own check: versor.h); versor apply
 *     writes 3 numbers.
 */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "fuzz_check.h"
#include <garotor/garotor.h>

int garotor_main(int argc, char **argv);
extern size_t tio_read_block; /* tools/textio.h */

static char dir[256], in_path[300], vel_path[300], out_path[300], svg_path[300], html_path[300];

static void cleanup(void)
{
    unlink(in_path);
    unlink(vel_path);
    unlink(out_path);
    unlink(svg_path);
    unlink(html_path);
    rmdir(dir);
}

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    const char *base = getenv("TMPDIR");
    if (!base || !*base)
        base = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    snprintf(dir, sizeof dir, "%s/garotor-fuzz-XXXXXX", base);
    if (!mkdtemp(dir)) {
        perror("fuzz_tool: mkdtemp");
        exit(1);
    }
    snprintf(in_path, sizeof in_path, "%s/in", dir);
    snprintf(vel_path, sizeof vel_path, "%s/vel", dir);
    snprintf(out_path, sizeof out_path, "%s/out", dir);
    snprintf(svg_path, sizeof svg_path, "%s/pic.svg", dir);
    snprintf(html_path, sizeof html_path, "%s/page.html", dir);
    atexit(cleanup);
    return 0;
}

static int write_file(const char *path, const uint8_t *p, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return -1;
    size_t w = n ? fwrite(p, 1, n, f) : 0;
    return (fclose(f) != 0 || w != n) ? -1 : 0;
}

/* Only the target's own files may be in the directory. */
static void check_no_stray_files(int allow_out)
{
    DIR *d = opendir(dir);
    FZ_CHECK(d != NULL, "cannot list %s", dir);
    struct dirent *e;
    while ((e = readdir(d))) {
        const char *nm = e->d_name;
        if (!strcmp(nm, ".") || !strcmp(nm, "..") || !strcmp(nm, "in") || !strcmp(nm, "vel"))
            continue;
        if (allow_out && (!strcmp(nm, "out") || !strcmp(nm, "pic.svg") || !strcmp(nm, "page.html")))
            continue;
        closedir(d);
        FZ_CHECK(0, "file '%s' left behind (exit status %s)", nm, allow_out ? "0" : "2");
    }
    closedir(d);
}

enum { K_EXP, K_LOG, K_INTERP, K_VERSOR };
enum { V_EXP, V_LOG, V_APPLY };

/* The numbers of item `want` (0-based) of the input file, as textio.c reads
   them (the first line skipped with --header, a byte-order mark, '#' lines
   and blank lines skipped, whitespace or a comma between numbers): k numbers
   into v, or -1 when it is not there, not k numbers, or too long to read here. */
static int input_line(const uint8_t *p, size_t n, int header, long want, double *v, int k)
{
    long line = -1, phys = 0;
    for (size_t i = 0; i < n;) {
        const char *ln = (const char *)p + i, *eol = memchr(ln, '\n', n - i);
        size_t len = eol ? (size_t)(eol - ln) : n - i;
        i += len + 1;
        if (++phys == 1 && header)
            continue;
        char buf[4096];
        if (len >= sizeof buf)
            return -1;
        memcpy(buf, ln, len);
        buf[len] = '\0';
        char *s = buf;
        if (phys == 1 && strncmp(s, "\xEF\xBB\xBF", 3) == 0)
            s += 3;
        while (*s == ' ' || *s == '\t' || *s == '\r') s++;
        if (!*s || *s == '#')
            continue;
        if (++line < want)
            continue;
        int m = 0;
        for (char *e; *s; s = e) {
            while (*s == ' ' || *s == '\t' || *s == '\r' || *s == ',') s++;
            if (!*s)
                break;
            double x = strtod(s, &e);
            if (e == s || m >= k)
                return -1;
            v[m++] = x;
        }
        return m == k ? 0 : -1;
    }
    return -1;
}

/* versor: what a line of output says about its line of input. */
static void check_versor(int verb, const double *v, int k, long lineno, const uint8_t *in, size_t nin,
                         int header)
{
    static const int width[] = {32, 10, 3};
    FZ_CHECK(k == width[verb], "versor: output line %ld has %d numbers", lineno, k);
    ga_mv R = ga_mv_zero();
    if (verb == V_EXP) {
        memcpy(R.c, v, 32 * sizeof *v);
        double sc = fmax(1.0, ga_mv_maxabs(R));
        for (int i = 0; i < 32; i++)
            if (ga_blade_grade(i) % 2)
                FZ_CHECK(R.c[i] == 0.0, "versor exp: output line %ld has an odd part", lineno);
        /* scaled by a power of two first, so that R ~R cannot overflow */
        int e;
        frexp(sc, &e);
        ga_mv Rs = ga_mv_scale(R, ldexp(1.0, -e)), rr = ga_mv_gp(Rs, ga_mv_reverse(Rs));
        rr.c[0] -= ldexp(1.0, -2 * e);
        FZ_CHECK(ga_mv_maxabs(rr) <= 1e-9 * ldexp(sc, -e) * ldexp(sc, -e),
                 "versor exp: output line %ld: R ~R - 1 = %.3g relative", lineno, ga_mv_maxabs(rr));
    } else if (verb == V_LOG) {
        double r[32];
        if (input_line(in, nin, header, lineno - 1, r, 32) != 0)
            return; /* a line too long to read back here */
        ga_mv B = ga_mv_zero(), X = ga_mv_zero();
        memcpy(B.c + GA_BLADE_E12, v, 10 * sizeof *v);
        memcpy(X.c, r, sizeof r);
        double d = ga_mv_maxabs(ga_mv_sub(ga_mv_exp(B), X)) / fmax(1.0, ga_mv_maxabs(X));
        FZ_CHECK(d <= 1e-9, "versor log: output line %ld: exp(log R) misses R by %.3g", lineno, d);
    }
}

/* Read the output back and check it. */
/* ofmt: interp's --output-format (0 mat, 1 pose, 2 tum, 3 kitti, 4 csv), or
   what --format implies */
static void check_output(int kind, int affine, int ofmt, int verb, const uint8_t *in, size_t nin, int header)
{
    int pose = ofmt == 1 || ofmt == 2 || ofmt == 4, kitti = ofmt == 3;
    FILE *f = fopen(out_path, "r");
    FZ_CHECK(f != NULL, "exit status 0 but no output file");
    char *line = NULL;
    size_t cap = 0;
    int width = -1;
    long lineno = 0;
    while (getline(&line, &cap, f) >= 0) {
        lineno++;
        if (kind == K_INTERP && ofmt == 4) { /* csv: a header line, then numbers and commas */
            if (lineno == 1) {
                FZ_CHECK(!strncmp(line, "t,", 2), "csv output: no header line");
                continue;
            }
            for (char *c = line; *c; c++)
                if (*c == ',')
                    *c = ' ';
        }
        double v[64];
        int k = 0;
        char *s = line, *end;
        for (;;) {
            while (*s == ' ' || *s == '\n') s++;
            if (!*s)
                break;
            double x = strtod(s, &end);
            FZ_CHECK(end != s, "output line %ld: not a number: %.40s", lineno, s);
            FZ_CHECK(isfinite(x), "output line %ld, number %d is %g", lineno, k + 1, x);
            FZ_CHECK(k < 64, "output line %ld has more than 64 numbers", lineno);
            v[k++] = x;
            s = end;
        }
        /* interp: t and the pose (8 or 17), then with --with the velocity and
           acceleration: 6 numbers each (a twist), or 16 each on affine */
        if (kind == K_VERSOR) {
            FZ_CHECK(width < 0 || k == width, "output line %ld: %d numbers after %d", lineno, k, width);
            width = k;
            check_versor(verb, v, k, lineno, in, nin, header);
            continue;
        }
        int base = kind == K_INTERP ? (kitti ? 12 : k >= 17 && !pose ? 17 : 8) : k, extra = k - base;
        FZ_CHECK(kind == K_INTERP ? extra == 0 || extra == 6 || extra == 12 || extra == 18 || extra == 16 ||
                                        extra == 32 || extra == 48
                                  : k == 6 || k == 16,
                 "output line %ld has %d numbers", lineno, k);
        FZ_CHECK(width < 0 || k == width, "output line %ld: %d numbers after %d", lineno, k, width);
        width = k;
        const double *m = NULL;
        if (kind == K_EXP && !affine && k == 16)
            m = v;
        if (kind == K_INTERP && !affine && base == 17)
            m = v + 1;
        if (kind == K_INTERP && !affine && kitti) /* 3 x 4: the last row implied */
            m = v;
        if (m) {
            FZ_CHECK(kitti || (m[12] == 0 && m[13] == 0 && m[14] == 0 && m[15] == 1),
                     "output line %ld: last row not 0 0 0 1", lineno);
            for (int r = 0; r < 3; r++)
                for (int c = 0; c < 3; c++) {
                    double d = m[r] * m[c] + m[4 + r] * m[4 + c] + m[8 + r] * m[8 + c];
                    FZ_CHECK(fabs(d - (r == c)) <= 1e-9, "output line %ld: rotation not orthonormal (%.3g)",
                             lineno, fabs(d - (r == c)));
                }
        }
        if (kind == K_INTERP && affine && base == 17)
            FZ_CHECK(v[13] == 0 && v[14] == 0 && v[15] == 0 && v[16] == 1,
                     "output line %ld: affine sample's last row not 0 0 0 1", lineno);
        if (kind == K_LOG && !affine && k == 6) {
            double th = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            FZ_CHECK(th <= 3.141592653589793 * (1 + 1e-15), "output line %ld: angle %.17g > pi", lineno, th);
        }
        if (kind == K_INTERP && pose && base == 8) {
            double qn = sqrt(v[4] * v[4] + v[5] * v[5] + v[6] * v[6] + v[7] * v[7]);
            FZ_CHECK(fabs(qn - 1) <= 1e-9, "output line %ld: quaternion norm %.17g", lineno, qn);
        }
    }
    free(line);
    fclose(f);
}

/* A file the tool read with exit status 0: no NUL byte, no line (the bytes
   before its newline) longer than max. */
static void check_read_ok(const char *what, const uint8_t *p, size_t n, size_t max)
{
    size_t len = 0;
    for (size_t i = 0; i < n; i++) {
        FZ_CHECK(p[i] != 0, "exit status 0, but the %s has a NUL byte at offset %zu", what, i);
        len = p[i] == '\n' ? 0 : len + 1;
        FZ_CHECK(len <= max, "exit status 0, but the %s has a line longer than --max-line %zu", what, max);
    }
}

#define MAXARG 40

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    /* line 1: the command line */
    const uint8_t *nl = memchr(data, '\n', size);
    size_t l1 = nl ? (size_t)(nl - data) : size;
    if (l1 > 400)
        return 0;
    char cmdline[401];
    memcpy(cmdline, data, l1);
    cmdline[l1] = '\0';
    if (memchr(cmdline, '\0', l1))
        return 0; /* a NUL would cut an argument short: not a command line */
    const uint8_t *rest = nl ? nl + 1 : data + size;
    size_t nrest = (size_t)(data + size - rest);

    /* split off the velocity file at a line "%%" */
    const uint8_t *vel = NULL;
    size_t nin = nrest, nvel = 0;
    for (size_t i = 0; i + 2 <= nrest; i++)
        if ((i == 0 || rest[i - 1] == '\n') && rest[i] == '%' && rest[i + 1] == '%' &&
            (i + 2 == nrest || rest[i + 2] == '\n')) {
            nin = i;
            vel = rest + i + 2 + (i + 2 < nrest);
            nvel = (size_t)(data + size - vel);
            break;
        }

    /* --name=VALUE is --name VALUE to the tool: split it here too, so that
       the filters below see every option's value (a --samples=HUGE or an
       --out=FILE would escape them) */
    for (char *c = cmdline, *word = cmdline; *c; c++) {
        if (*c == ' ' || *c == '\t' || *c == '\r')
            word = c + 1;
        else if (*c == '=' && word && word[0] == '-' && word[1] == '-') {
            *c = ' ';
            word = NULL; /* the value, split no further: --a=--b=c is --a and --b=c */
        }
    }
    /* the tool takes --help (or -h) anywhere, even where an option's value
       goes ("log --group --help" prints the usage, status 0, no output
       file): skipped like --help itself (fuzz/regress/tool/help-as-value) */
    {
        char scan[401], *sv = NULL;
        memcpy(scan, cmdline, l1 + 1);
        for (char *t = strtok_r(scan, " \t\r", &sv); t; t = strtok_r(NULL, " \t\r", &sv))
            if (!strcmp(t, "--help") || !strcmp(t, "-h"))
                return 0;
    }
    /* argv: filter the command line */
    char *argv[MAXARG + 12];
    int argc = 0;
    argv[argc++] = "garotor";
    int want_vel = 0, want_svg = 0, want_html = 0, kind = -1, affine = 0, pose = 0, verb = -1, header = 0;
    int kitti = 0, ofmt = -1, text = 0; /* --format kitti, --output-format, --text */
    size_t max_line = (size_t)1 << 20;  /* the tool's default (TIO_MAX_LINE) */
    static char capped[3][32];
    /* the span of the keys' times (the first number of each input line), for
       capping --rate below: HZ is lowered so that it gives at most 4096
       samples over that span (a rate over months of epoch stamps is legal
       and merely large: streamed in constant memory, but slow, and held with
       --svg: fuzz/regress/tool/interp-rate-epoch-span-oom) */
    double tmin = INFINITY, tmax = -INFINITY;
    /* a UTF-8 byte-order mark opening the input is skipped, as the tool
       skips it (else the first time is missed and the span can be 0:
       fuzz/regress/tool/interp-rate-bom-span) */
    size_t i0 = nin >= 3 && !memcmp(rest, "\xef\xbb\xbf", 3) ? 3 : 0;
    for (size_t i = i0; i < nin;) {
        const char *ln = (const char *)rest + i, *eol = memchr(ln, '\n', nin - i);
        size_t len = eol ? (size_t)(eol - ln) : nin - i;
        char num[512];
        size_t m = len < sizeof num - 1 ? len : sizeof num - 1;
        /* the whole first number, or the span is underestimated (a time of
           72 digits cut to 63 read 1e7 times too small: a --rate of 4e10
           samples, fuzz/regress/tool/interp-rate-long-stamp) */
        size_t w = 0;
        while (w < len && strchr(" \t\r,", ln[w])) w++;
        while (w < len && !strchr(" \t\r,", ln[w])) w++;
        if (w >= sizeof num)
            return 0;
        memcpy(num, ln, m);
        num[m] = '\0';
        char *e;
        double t = strtod(num, &e);
        if (e != num && isfinite(t)) {
            tmin = fmin(tmin, t);
            tmax = fmax(tmax, t);
        }
        i += len + 1;
    }
    char *save = NULL;
    for (char *tok = strtok_r(cmdline, " \t\r", &save); tok; tok = strtok_r(NULL, " \t\r", &save)) {
        if (argc == 1) {
            if (!strcmp(tok, "exp"))
                kind = K_EXP;
            else if (!strcmp(tok, "log"))
                kind = K_LOG;
            else if (!strcmp(tok, "interp"))
                kind = K_INTERP;
            else if (!strcmp(tok, "versor"))
                kind = K_VERSOR;
            else
                return 0;
            argv[argc++] = tok;
            continue;
        }
        if (kind == K_VERSOR && argc == 2) /* the operation, as given */
            verb = !strcmp(tok, "exp")   ? V_EXP
                 : !strcmp(tok, "log")   ? V_LOG
                 : !strcmp(tok, "apply") ? V_APPLY
                                         : -1;
        header |= !strcmp(tok, "--header");
        text |= !strcmp(tok, "--text");
        if (argc >= MAXARG)
            return 0;
        if (!strcmp(tok, "--help") || !strcmp(tok, "-h"))
            return 0;
        /* every file the tool reads or writes is the harness's, in its
           directory (a --html FILE passed through wrote pages into the
           working directory, and could overwrite any file there) */
        if (!strcmp(tok, "--in") || !strcmp(tok, "--out") || !strcmp(tok, "--svg") ||
            !strcmp(tok, "--html") || !strcmp(tok, "--velocities")) {
            want_vel |= !strcmp(tok, "--velocities");
            want_svg |= !strcmp(tok, "--svg");
            want_html |= !strcmp(tok, "--html");
            strtok_r(NULL, " \t\r", &save); /* and its value */
            continue;
        }
        if (!strcmp(tok, "--group")) {
            char *v = strtok_r(NULL, " \t\r", &save);
            argv[argc++] = tok;
            if (v) {
                argv[argc++] = v;
                affine = !strcmp(v, "affine");
            }
            continue;
        }
        if (!strcmp(tok, "--max-line")) { /* passed on; its value kept for the checks */
            char *v = strtok_r(NULL, " \t\r", &save);
            argv[argc++] = tok;
            if (v) {
                argv[argc++] = v;
                max_line = (size_t)strtoull(v, NULL, 10);
            }
            continue;
        }
        if (!strcmp(tok, "--format")) {
            char *v = strtok_r(NULL, " \t\r", &save);
            argv[argc++] = tok;
            if (v) {
                argv[argc++] = v;
                pose = !strcmp(v, "pose");
                kitti = !strcmp(v, "kitti");
            }
            continue;
        }
        if (!strcmp(tok, "--output-format")) {
            char *v = strtok_r(NULL, " \t\r", &save);
            argv[argc++] = tok;
            if (v) {
                static const char *const fmt[] = {"mat", "pose", "tum", "kitti", "csv"};
                argv[argc++] = v;
                for (int i = 0; i < 5; i++)
                    if (!strcmp(v, fmt[i]))
                        ofmt = i;
            }
            continue;
        }
        if (!strcmp(tok, "--rate")) {
            char *v = strtok_r(NULL, " \t\r", &save);
            argv[argc++] = tok;
            if (v) {
                char *end;
                double hz = strtod(v, &end), span = tmax - tmin;
                if (*end == '\0' && hz > 0 && span > 0 && isfinite(span) && hz * span > 4096) {
                    snprintf(capped[2], sizeof capped[2], "%.17g", 4096 / span);
                    v = capped[2];
                }
                argv[argc++] = v;
            }
            continue;
        }
        if (!strcmp(tok, "--samples") || !strcmp(tok, "--step")) {
            int is_step = tok[2] == 's' && tok[3] == 't';
            char *v = strtok_r(NULL, " \t\r", &save);
            argv[argc++] = tok;
            if (v) {
                char *end;
                double x = is_step ? strtod(v, &end) : (double)strtol(v, &end, 10);
                if (!is_step && *end == '\0' && x > 4096) {
                    snprintf(capped[0], sizeof capped[0], "4096");
                    v = capped[0];
                }
                if (is_step && *end == '\0' && x > 0 && x < 1e-3) {
                    snprintf(capped[1], sizeof capped[1], "1e-3");
                    v = capped[1];
                }
                argv[argc++] = v;
            }
            continue;
        }
        argv[argc++] = tok;
    }
    if (kind < 0)
        return 0;
    char *in_opt = "--in", *out_opt = "--out", *vel_opt = "--velocities", *svg_opt = "--svg",
         *html_opt = "--html";
    argv[argc++] = in_opt;
    argv[argc++] = in_path;
    if (want_vel) {
        argv[argc++] = vel_opt;
        argv[argc++] = vel_path;
    }
    if (want_svg) {
        argv[argc++] = svg_opt;
        argv[argc++] = svg_path;
    }
    if (want_html) {
        argv[argc++] = html_opt;
        argv[argc++] = html_path;
    }
    argv[argc++] = out_opt;
    argv[argc++] = out_path;
    argv[argc] = NULL;

    FZ_CHECK(write_file(in_path, rest, nin) == 0, "cannot write %s", in_path);
    if (want_vel)
        FZ_CHECK(write_file(vel_path, vel ? vel : rest, vel ? nvel : 0) == 0, "cannot write %s", vel_path);

    tio_read_block = 1 + size % 61;
    int rc = garotor_main(argc, argv);
    FZ_CHECK(rc == 0 || rc == 2, "exit status %d", rc);
    if (rc == 2) {
        check_no_stray_files(0);
    } else {
        FZ_CHECK(kind != K_VERSOR || verb >= 0, "versor: exit status 0 for an unknown operation");
        check_read_ok("input", rest, nin, max_line);
        if (want_vel && vel)
            check_read_ok("velocity file", vel, nvel, max_line);
        /* versor --text writes blade names: its lines are not checked as numbers */
        if (!(kind == K_VERSOR && text))
            check_output(kind, affine, ofmt >= 0 ? ofmt : pose ? 1 : kitti ? 3 : 0, verb, rest, nin, header);
        check_no_stray_files(1);
    }
    unlink(out_path);
    unlink(svg_path);
    unlink(html_path);
    unlink(vel_path);
    return 0;
}
