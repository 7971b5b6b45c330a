/* tools/columns.c: see columns.h. Poses in any column layout, a CSV with a
 * header row read by name (a `rostopic echo -p` export: columns that are not
 * numbers, such as a frame id, are skipped), read into the items of a pose
 * file (t x y z qx qy qz qw), so that `garotor interp` reads them as
 * --format pose and `garotor eval` as TUM. */
#include "columns.h"

#include <garotor/garotor.h>

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

enum { NROLE = COL_ROLES, MAX_FIELDS = 4096 };
static const char *const role_name[NROLE] = {"t", "x", "y", "z", "qx", "qy", "qz", "qw"};

/* The layout --columns gives: each role's column (from 0; -1 none yet) or
 * the header name to find; by_name: roles not given are found in the header
 * by their names. */
typedef struct {
    long col[NROLE];
    char *want[NROLE];
    int by_name, header, positional, pairs;
} col_spec;

static int role_of(const char *w, size_t len)
{
    for (int r = 0; r < NROLE; r++)
        if (strlen(role_name[r]) == len && strncmp(w, role_name[r], len) == 0)
            return r;
    return -1;
}

static int spec_error(const char *cmd, const char *what, const char *word, size_t len)
{
    fprintf(stderr, "garotor %s: --columns: %s'%.*s'%s\n", cmd, what, (int)len, word,
            *what ? ""
                  : " is not a column: name t x y z qx qy qz qw (or - to skip one) in the file's order, or "
                    "ROLE=COLUMN (a number from 1, or a name in the header row), or header");
    return -1;
}

/* --columns LIST into cs (its names point into buf, a copy of LIST). */
static int parse_spec(const char *cmd, char *buf, col_spec *cs)
{
    memset(cs, 0, sizeof *cs);
    for (int r = 0; r < NROLE; r++) cs->col[r] = -1;
    long pos = 0;
    for (char *w = buf;;) {
        size_t len = strcspn(w, ",");
        char *eq = memchr(w, '=', len);
        int last = w[len] == '\0';
        w[len] = '\0';
        if (strcmp(w, "header") == 0)
            cs->by_name = cs->header = 1;
        else if (eq) {
            int r = role_of(w, (size_t)(eq - w));
            const char *c = eq + 1;
            if (r < 0 || !*c)
                return spec_error(cmd, "", w, len);
            if (cs->col[r] >= 0 || cs->want[r])
                return spec_error(cmd, "a role given twice: ", w, (size_t)(eq - w));
            char *end;
            errno = 0;
            long k = strtol(c, &end, 10);
            if (*c >= '0' && *c <= '9' && !*end && !errno && k >= 1 && k <= MAX_FIELDS)
                cs->col[r] = k - 1;
            else {
                cs->want[r] = (char *)c;
                cs->header = 1;
            }
            cs->pairs = 1;
        } else {
            int r = strcmp(w, "-") == 0 ? -2 : role_of(w, len);
            if (r == -1)
                return spec_error(cmd, "", w, len);
            if (r >= 0 && cs->col[r] >= 0)
                return spec_error(cmd, "a role given twice: ", w, len);
            if (r >= 0)
                cs->col[r] = pos;
            pos++;
            cs->positional = 1;
        }
        if (last)
            break;
        w += len + 1;
    }
    if (cs->positional && (cs->pairs || cs->by_name)) {
        fprintf(
            stderr,
            "garotor %s: --columns: either the columns in order (t,x,...) or ROLE=COLUMN pairs and header, "
            "not both\n",
            cmd);
        return -1;
    }
    for (int r = 0; r < NROLE && !cs->by_name; r++)
        if (cs->col[r] < 0 && !cs->want[r]) {
            fprintf(stderr, "garotor %s: --columns gives no column for %s\n", cmd, role_name[r]);
            return -1;
        }
    return 0;
}

/* The fields of a line, in place: split at the commas outside quotes when
 * it has one, else at runs of spaces and tabs; each trimmed of spaces, tabs
 * and '\r'. A field may be quoted as CSV quotes it (RFC 4180: "a,b" is one
 * field, "" inside is one '"'); the quotes are removed. The count, or -1
 * with *bad the field (from 1) and *why what is wrong with its quoting. */
static long split(char *s, char **f, size_t *bad, const char **why)
{
    size_t n = 0;
    int comma = 0, quoted = 0;
    for (const char *c = s; *c && !comma; c++) {
        quoted ^= *c == '"';
        comma = *c == ',' && !quoted;
    }
    for (;;) {
        while (*s == ' ' || *s == '\t' || *s == '\r') s++;
        if (!comma && !*s)
            break;
        char *e, *t;
        *bad = n + 1;
        if (*s == '"') { /* quoted: up to the closing quote, "" is one quote */
            char *r = s + 1, *w = s;
            for (;;) {
                if (!*r) {
                    *why = "a quoted field with no closing quote (a field is quoted on one line)";
                    return -1;
                }
                if (*r == '"' && r[1] != '"')
                    break;
                r += *r == '"';
                *w++ = *r++;
            }
            t = w;
            e = r + 1;
            while (*e == ' ' || *e == '\t' || *e == '\r') e++;
            if (*e && !(comma && *e == ',') && !(!comma && e > r + 1)) {
                *why = "text after the closing quote of a quoted field (a '\"' inside one is written '\"\"')";
                return -1;
            }
            if (!comma && *e) /* the blank after the quote is the separator */
                e--;
        } else {
            e = comma ? s + strcspn(s, ",") : s + strcspn(s, " \t\r");
            if (memchr(s, '"', (size_t)(e - s))) {
                *why = "a '\"' inside a field that is not quoted (quote the whole field: \"a\"\"b\")";
                return -1;
            }
            t = e;
            while (t > s && (t[-1] == ' ' || t[-1] == '\t' || t[-1] == '\r')) t--;
        }
        int last = *e == '\0';
        *t = '\0';
        if (n < MAX_FIELDS)
            f[n++] = s;
        if (last)
            break;
        s = e + 1;
    }
    return (long)n;
}

/* The fields of line i of L, or -1 after a message naming the line and the
 * field whose quoting is wrong. */
static long fields(const tio_lines_text *L, size_t i, char *s, char **f)
{
    size_t bad = 0;
    const char *why = "";
    long n = split(s, f, &bad, &why);
    if (n < 0)
        fprintf(stderr, "garotor: %s:%ld: column %zu: %s\n", L->name, L->line[i], bad, why);
    return n;
}

/* Does a header name look like role r? The role's own name (any case), and
 * the names of TUM, ROS (`rostopic echo -p`) and common CSV exports. */
static int looks_like(const char *name, int r)
{
    static const char *const t_names[] = {"time", "timestamp", "stamp", "%time", "#timestamp", "# timestamp"};
    static const char *const tails[NROLE] = {".stamp",        "position.x",    "position.y",
                                             "position.z",    "orientation.x", "orientation.y",
                                             "orientation.z", "orientation.w"};
    static const char *const alt[NROLE] = {"#t", "tx", "ty", "tz", "#qx", "#qy", "#qz", "#qw"};
    size_t n = strlen(name), k = strlen(tails[r]);
    if (strcasecmp(name, role_name[r]) == 0 || strcasecmp(name, alt[r]) == 0)
        return 1;
    if (n >= k && strcasecmp(name + n - k, tails[r]) == 0)
        return 1;
    for (size_t i = 0; r == 0 && i < sizeof t_names / sizeof t_names[0]; i++)
        if (strcasecmp(name, t_names[i]) == 0)
            return 1;
    return 0;
}

/* Each role's column from the header row's names. */
static int resolve(const tio_lines_text *L, char *hdr, col_spec *cs)
{
    static char *f[MAX_FIELDS];
    /* "#timestamp,..." (EuRoC), "# timestamp tx ty ..." (TUM): the '#' is no
       part of a name (a field of its own, it would shift every column by one) */
    if (hdr[0] == '#')
        hdr++;
    long nf = fields(L, 0, hdr, f);
    if (nf < 0)
        return -1;
    size_t n = (size_t)nf;
    for (int r = 0; r < NROLE; r++) {
        if (cs->col[r] >= 0)
            continue;
        long found = -1;
        for (size_t c = 0; c < n; c++) {
            int hit = cs->want[r] ? strcmp(f[c], cs->want[r]) == 0 : looks_like(f[c], r);
            if (hit && found >= 0 && !cs->want[r]) {
                fprintf(stderr,
                        "garotor: %s:%ld: columns %ld (%s) and %zu (%s) both look like %s: pick one with "
                        "--columns header,%s=NAME\n",
                        L->name, L->line[0], found + 1, f[found], c + 1, f[c], role_name[r], role_name[r]);
                return -1;
            }
            if (hit && found < 0)
                found = (long)c;
        }
        if (found < 0) {
            if (cs->want[r])
                fprintf(stderr, "garotor: %s:%ld: no column named '%s' in the header (--columns %s=%s)\n",
                        L->name, L->line[0], cs->want[r], role_name[r], cs->want[r]);
            else
                fprintf(stderr,
                        "garotor: %s:%ld: no column of the header looks like %s: name it, --columns "
                        "header,%s=NAME (or a column number)\n",
                        L->name, L->line[0], role_name[r], role_name[r]);
            return -1;
        }
        cs->col[r] = found;
    }
    return 0;
}

int col_check_list(const char *cmd, const char *list)
{
    char *buf = malloc(strlen(list) + 1);
    col_spec cs;
    if (!buf) {
        fprintf(stderr, "garotor: out of memory\n");
        return -1;
    }
    strcpy(buf, list);
    int rc = parse_spec(cmd, buf, &cs);
    free(buf);
    return rc;
}

static int oom(void)
{
    fprintf(stderr, "garotor: out of memory\n");
    return -1;
}

int col_read_poses(const char *cmd, const char *path, const char *list, const tio_read_opts *ro,
                   tio_items *out, long col[COL_ROLES])
{
    char *buf = malloc(strlen(list) + 1);
    tio_lines_text L = {0};
    tio_items it = {0};
    static char *f[MAX_FIELDS];
    col_spec cs;
    int rc = -1;
    if (!buf)
        return oom();
    strcpy(buf, list);
    if (parse_spec(cmd, buf, &cs) || tio_read_lines(path, ro, &L))
        goto done;
    it.name = L.name;
    size_t first = 0;
    if (cs.header || ro->header) { /* the first line names the columns */
        if (L.n == 0) {
            fprintf(stderr, "garotor: %s: no header row (--columns %s reads one)\n", L.name, list);
            goto done;
        }
        if (cs.header && resolve(&L, L.text[0], &cs))
            goto done;
        first = 1;
    }
    it.value = malloc((L.n ? L.n : 1) * NROLE * sizeof *it.value);
    it.item = malloc((L.n ? L.n : 1) * sizeof *it.item);
    it.first = calloc(L.n ? L.n : 1, sizeof *it.first);
    if (!it.value || !it.item || !it.first) {
        oom();
        goto done;
    }
    for (size_t i = first; i < L.n; i++) {
        char *s = L.text[i] + strspn(L.text[i], " \t");
        if (*s == '#')
            continue;
        long nf = fields(&L, i, s, f);
        if (nf < 0)
            goto done;
        size_t n = (size_t)nf, k = it.n;
        it.item[k] = (tio_item){k * NROLE, NROLE, L.line[i]};
        it.n++;
        for (int r = 0; r < NROLE; r++) {
            long c = cs.col[r];
            if ((size_t)c >= n) {
                tio_error(&it, k, "%zu columns, but --columns reads column %ld (%s)", n, c + 1, role_name[r]);
                goto done;
            }
            char *end;
            double v = strtod(f[c], &end);
            if (end == f[c] || *end) {
                tio_error(&it, k, "column %ld (%s): '%s' is not a number", c + 1, role_name[r], f[c]);
                goto done;
            }
            if (!isfinite(v)) {
                tio_error(&it, k, "column %ld (%s): '%s' is not finite", c + 1, role_name[r], f[c]);
                goto done;
            }
            if (r >= 4 && fabs(v) > 1.0 + GA_SE3_NORMALIZE_TOL) {
                tio_error(&it, k,
                          "column %ld (%s) is %s: beyond 1, not a unit quaternion's; is that column the "
                          "quaternion's? (--columns %s)",
                          c + 1, role_name[r], f[c], list);
                goto done;
            }
            it.value[k * NROLE + (size_t)r] = v;
        }
        size_t len = strlen(f[cs.col[0]]);
        if (!(it.first[k] = malloc(len + 1))) {
            oom();
            goto done;
        }
        memcpy(it.first[k], f[cs.col[0]], len + 1);
    }
    *out = it;
    memset(&it, 0, sizeof it);
    if (col)
        for (int r = 0; r < NROLE; r++) col[r] = cs.col[r];
    rc = 0;
done:
    if (it.first)
        for (size_t i = 0; i < it.n; i++) free(it.first[i]);
    free(it.first);
    free(it.value);
    free(it.item);
    tio_texts_free(&L);
    free(buf);
    return rc;
}
