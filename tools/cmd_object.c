/* tools/cmd_object.c: `garotor object OP`, conformal objects in a pipe
 * (docs/tool.md): built from points or parameters, read back with their
 * error bounds, met, joined, moved, and the rotor between two of them, one
 * item a line, multivectors written with blade names (mvtext.h). A line's
 * fields are separated by ';'; each object field is a multivector
 * (`2e1235`) or a constructor (`sphere 0 0 0 1`).
 * Everything is computed before anything is written: an error on any line
 * leaves no output. */
#include "cli.h"
#include "mvtext.h"
#include "textio.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <garotor/garotor.h>

enum { OP_BUILD, OP_READ, OP_MEET, OP_JOIN, OP_MEET_REL, OP_MOVE, OP_BETWEEN, OP_INTERP, OP_COUNT };
static const char *const op_name[OP_COUNT] = {"build",    "read", "meet",    "join",
                                              "meet-rel", "move", "between", "interp"};
/* fields a line holds, and what they are, for messages */
static const int op_fields[OP_COUNT] = {1, 1, 2, 2, 2, 2, 2, 3};
static const char *const op_form[OP_COUNT] = {
    "an object", "an object", "A; B", "A; B", "A; B", "V; X (a versor, then an object)", "A; B", "A; B; t"};

/* The constructors: a word, then numbers. Objects are built in direct form
   (a vector is a point, a sphere or plane a 4-vector), as ga_mv_join and
   ga_mv_meet_rel take them. */
enum {
    C_POINT,
    C_PAIR,
    C_LINE,
    C_CIRCLE,
    C_PLANE,
    C_SPHERE,
    C_TRANSLATION,
    C_ROTATION,
    C_DILATION,
    C_REFLECTION,
    C_INVERSION,
    C_TRANSVERSION,
    C_COUNT
};
static const struct {
    const char *name;
    int n1, n2; /* the numbers it takes (n2: a second form, 0 if none) */
    const char *what;
} ctor[C_COUNT] = {
    {"point", 3, 0, "x y z"},
    {"pair", 6, 0, "two points"},
    {"line", 6, 0, "two points"},
    {"circle", 9, 0, "three points"},
    {"plane", 9, 4, "three points, or a unit normal and a distance"},
    {"sphere", 12, 4, "four points, or a centre and a radius"},
    {"translation", 3, 0, "a vector"},
    {"rotation", 4, 0, "an axis and an angle in radians"},
    {"dilation", 4, 0, "a centre and a factor > 0"},
    {"reflection", 4, 0, "a normal and a distance"},
    {"inversion", 4, 0, "a centre and a radius"},
    {"transversion", 3, 0, "a vector"},
};

static ga_vec3 v3(const double *v) { return (ga_vec3){v[0], v[1], v[2]}; }

/* The object (or versor) written in field f of line i: a constructor or a
   multivector; 0, or -1 after a message. */
static int operand(const tio_texts *t, size_t i, mvt_field f, ga_mv *out)
{
    const char *s = t->text[i] + f.at;
    size_t k = 0;
    while (k < f.len && (s[k] == ' ' || s[k] == '\t')) k++;
    size_t w = 0;
    while (k + w < f.len && s[k + w] >= 'a' && s[k + w] <= 'z') w++;
    /* a word that is not a blade name (e, then digits) names a constructor */
    if (w == 0 || (s[k] == 'e' && w == 1))
        return mvt_parse(t, i, f, out);
    int c = 0;
    while (c < C_COUNT && !(strlen(ctor[c].name) == w && strncmp(s + k, ctor[c].name, w) == 0)) c++;
    if (c == C_COUNT)
        return tio_text_error(t, i, f.at + k,
                              "unknown object '%.*s' (point, pair, line, circle, plane, sphere; translation, "
                              "rotation, dilation, reflection, inversion, transversion; or a multivector: "
                              "1 + 2e12)",
                              w > 40 ? 40 : (int)w, s + k);
    double v[12];
    int n = mvt_numbers(t, i, f, k + w, v, 12);
    if (n < 0)
        return -1;
    if (n != ctor[c].n1 && n != ctor[c].n2) {
        if (ctor[c].n2)
            return tio_text_error(t, i, f.at + k, "expected %d or %d numbers after '%s' (%s), found %d",
                                  ctor[c].n1, ctor[c].n2, ctor[c].name, ctor[c].what, n);
        return tio_text_error(t, i, f.at + k, "expected %d numbers after '%s' (%s), found %d", ctor[c].n1,
                              ctor[c].name, ctor[c].what, n);
    }
    ga_vec3 a = v3(v), b = v3(v + 3), p = v3(n > 6 ? v + 6 : v), q = v3(n > 9 ? v + 9 : v);
    switch (c) {
    case C_POINT: *out = ga_point_up(a); break;
    case C_PAIR: *out = ga_pointpair_from_points(a, b); break;
    case C_LINE: *out = ga_line_from_points(a, b); break;
    case C_CIRCLE: *out = ga_circle_from_points(a, b, p); break;
    case C_PLANE:
        if (n == 4) {
            double len = sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
            if (!(len > 0.0))
                return tio_text_error(t, i, f.at + k, "plane: the normal is 0");
            *out = ga_mv_dual(ga_plane_dual((ga_vec3){a.x / len, a.y / len, a.z / len}, v[3] / len));
        } else
            *out = ga_plane_from_points(a, b, p);
        break;
    case C_SPHERE:
        if (n == 4 && !(v[3] >= 0.0))
            return tio_text_error(t, i, f.at + k, "sphere: the radius must be >= 0, not %g", v[3]);
        *out = n == 4 ? ga_mv_dual(ga_sphere_dual(a, v[3])) : ga_sphere_from_points(a, b, p, q);
        break;
    case C_TRANSLATION: *out = ga_versor_translation(a); break;
    case C_ROTATION: *out = ga_versor_rotation(a, v[3]); break;
    case C_DILATION:
        if (ga_versor_dilation(a, v[3], out) != GA_OK)
            return tio_text_error(t, i, f.at + k, "dilation: the factor must be > 0, not %g", v[3]);
        break;
    case C_REFLECTION: *out = ga_versor_reflection(a, v[3]); break;
    case C_INVERSION: *out = ga_versor_inversion(a, v[3]); break;
    default: *out = ga_versor_transversion(a);
    }
    if (!ga_mv_isfinite(*out))
        return tio_text_error(t, i, f.at + k, "%s: %s", ctor[c].name, ga_status_string(GA_ERR_DOMAIN));
    return 0;
}

static const char *const kind_word[] = {"empty", "flatpoint", "line", "plane", "pair", "circle", "sphere"};
static const char *const reality_word[] = {"real", "tangent", "imaginary"};

/* The rigid-motion rotor V is, exactly (the 8 coefficients of ga_rotor_to_mv,
   e_i4 = e_i5, nothing else), on the group to 1e-9: 0 and *R; else -1. */
static int rigid(ga_mv V, ga_rotor *R)
{
    static const int in[] = {0,
                             GA_BLADE_E12,
                             GA_BLADE_E13,
                             GA_BLADE_E23,
                             GA_BLADE_E14,
                             GA_BLADE_E15,
                             GA_BLADE_E24,
                             GA_BLADE_E25,
                             GA_BLADE_E34,
                             GA_BLADE_E35,
                             GA_BLADE_E1234,
                             GA_BLADE_E1235};
    ga_mv rest = V;
    for (size_t k = 0; k < sizeof in / sizeof in[0]; k++) rest.c[in[k]] = 0.0;
    if (ga_mv_maxabs(rest) != 0.0 || V.c[GA_BLADE_E14] != V.c[GA_BLADE_E15] ||
        V.c[GA_BLADE_E24] != V.c[GA_BLADE_E25] || V.c[GA_BLADE_E34] != V.c[GA_BLADE_E35] ||
        V.c[GA_BLADE_E1234] != V.c[GA_BLADE_E1235])
        return -1;
    ga_rotor r = {V.c[0],
                  V.c[GA_BLADE_E12],
                  V.c[GA_BLADE_E13],
                  V.c[GA_BLADE_E23],
                  V.c[GA_BLADE_E14],
                  V.c[GA_BLADE_E24],
                  V.c[GA_BLADE_E34],
                  V.c[GA_BLADE_E1234]};
    if (ga_rotor_check(r, 1e-9) != GA_OK)
        return -1;
    /* the same multivector back, bit for bit: the reading above is right */
    ga_mv back = ga_rotor_to_mv(r);
    if (memcmp(back.c, V.c, sizeof V.c) != 0)
        return -1;
    *R = r;
    return 0;
}

/* One line: its result into r (a multivector, or for read the object) */
static int one(int op, const tio_texts *t, size_t i, ga_mv *r, ga_object *ob)
{
    mvt_field f[3];
    int nf = mvt_fields(t, i, f, op_fields[op]);
    if (nf < 0)
        return -1;
    if (nf != op_fields[op])
        return tio_text_error(t, i, 0, "expected %d fields separated by ';' (%s), found %d", op_fields[op],
                              op_form[op], nf);
    ga_mv A, B = ga_mv_zero();
    if (operand(t, i, f[0], &A) || (nf > 1 && operand(t, i, f[1], &B)))
        return -1;
    int st = GA_OK;
    size_t at = f[0].at;
    switch (op) {
    case OP_BUILD: *r = A; return 0;
    case OP_READ:
        st = ga_object_from_mv(A, ob);
        if (st == GA_ERR_SINGULAR)
            return tio_text_error(t, i, at,
                                  "0 is no object (the meet of objects in special position is 0: "
                                  "meet-rel gives what they share)");
        if (st != GA_OK)
            return tio_text_error(t, i, at, "not an object: %s", ga_status_string(st));
        return 0;
    case OP_MEET: *r = ga_mv_meet(A, B); return 0;
    case OP_JOIN: st = ga_mv_join(A, B, r); break;
    case OP_MEET_REL: st = ga_mv_meet_rel(A, B, r); break;
    case OP_MOVE: {
        ga_rotor R;
        if (rigid(A, &R) == 0) { /* the translation exact: ga_rotor_apply_mv */
            *r = ga_rotor_apply_mv(R, B);
            return 0;
        }
        st = ga_versor_apply(A, B, r);
        if (st == GA_ERR_ARG)
            return tio_text_error(t, i, at, "not a versor: it has both even and odd parts");
        if (st != GA_OK)
            return tio_text_error(t, i, at, "not a versor: %s", ga_status_string(st));
        return 0;
    }
    case OP_BETWEEN:
    case OP_INTERP: {
        double tt = 0.0;
        if (op == OP_INTERP) {
            int m = mvt_numbers(t, i, f[2], 0, &tt, 1);
            if (m < 0)
                return -1;
            if (m != 1)
                return tio_text_error(t, i, f[2].at, "expected 1 number (t: 0 is A, 1 is B), found %d", m);
        }
        st = op == OP_BETWEEN ? ga_versor_between(A, B, r) : ga_object_interp(A, B, tt, r);
        if (st == GA_ERR_ARG) {
            ga_object a, b;
            if (ga_object_from_mv(A, &a) == GA_OK && ga_object_from_mv(B, &b) == GA_OK)
                return tio_text_error(t, i, at, "no rotor takes a %s to a %s: the kinds differ",
                                      kind_word[a.kind], kind_word[b.kind]);
        }
        if (st == GA_ERR_DOMAIN)
            return tio_text_error(t, i, at,
                                  "no rotor takes a point (radius 0) to a round of radius > 0, or "
                                  "the other way (or it overflows)");
        if (st != GA_OK)
            return tio_text_error(t, i, at, "no rotor from A to B: %s", ga_status_string(st));
        return 0;
    }
    }
    if (st != GA_OK)
        return tio_text_error(t, i, at, "%s: %s", op_name[op], ga_status_string(st));
    return 0;
}

/* read's line: kind, reality, centre, direction, r2 and the bounds */
static void write_object(tio_out *out, const ga_object *o)
{
    char line[512];
    size_t k = (size_t)snprintf(line, sizeof line, "%s %s centre", kind_word[o->kind],
                                reality_word[o->reality]);
    const double v[] = {o->centre.x,    o->centre.y, o->centre.z, o->direction.x, o->direction.y,
                        o->direction.z, o->r2,       o->err,      o->r2_err,      o->angle_err};
    static const char *const label[] = {"", "",    "",     " direction", "",
                                        "", " r2", " err", " r2_err",    " angle_err"};
    for (int j = 0; j < 10; j++) {
        k += (size_t)snprintf(line + k, sizeof line - k, "%s ", label[j]);
        k += ga_double_format(v[j] == 0.0 ? 0.0 : v[j], line + k);
    }
    tio_out_text(out, line, k);
}

int cmd_object(const cli_opts *o)
{
    int op = 0;
    if (!o->verb) {
        fprintf(stderr, "garotor object: which one: build, read, meet, join, meet-rel, move, between or "
                        "interp?\n(garotor object --help shows the options)\n");
        return 2;
    }
    while (op < OP_COUNT && strcmp(o->verb, op_name[op]) != 0) op++;
    if (op == OP_COUNT) {
        fprintf(stderr,
                "garotor object: unknown operation '%s' (build, read, meet, join, meet-rel, move, between or "
                "interp)\n(garotor object --help shows the options)\n",
                o->verb);
        return 2;
    }
    tio_texts t;
    tio_read_opts ro = cli_input(o);
    if (tio_read_text(o->in, &ro, &t))
        return 2;
    ga_mv *res = malloc((t.n ? t.n : 1) * sizeof *res);
    ga_object *obs = malloc((t.n ? t.n : 1) * sizeof *obs);
    int ok = res && obs;
    if (!ok)
        fprintf(stderr, "garotor object: out of memory\n");
    for (size_t i = 0; i < t.n && ok; i++) {
        ok = !one(op, &t, i, &res[i], &obs[i]);
        if (ok && op != OP_READ && !ga_mv_isfinite(res[i]))
            ok = !tio_text_error(&t, i, 0, "%s: %s", op_name[op], ga_status_string(GA_ERR_DOMAIN));
    }
    tio_out out;
    if (ok && tio_out_open(&out, o->out) == 0) {
        char buf[GA_MV_TEXT_MAX];
        for (size_t i = 0; i < t.n; i++) {
            if (op == OP_READ)
                write_object(&out, &obs[i]);
            else
                tio_out_text(&out, buf, mvt_format(res[i], buf));
        }
        ok = tio_out_close(&out, 1) == 0;
    } else
        ok = 0;
    free(res);
    free(obs);
    tio_texts_free(&t);
    return ok ? 0 : 2;
}
