/* tools/textio.c: see textio.h. */
#define _POSIX_C_SOURCE 200809L
#include "textio.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int grow(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return 0;
    size_t c = *cap ? *cap : 64;
    while (c < need)
        c *= 2;
    void *q = realloc(*p, c * size);
    if (!q)
        return -1;
    *p = q;
    *cap = c;
    return 0;
}

int tio_error(const tio_items *items, size_t i, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "garotor: %s:%ld: ", items->name, items->item[i].line);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return -1;
}

void tio_free(tio_items *items)
{
    free(items->value);
    free(items->item);
    memset(items, 0, sizeof *items);
}

int tio_read(const char *path, int skip_header, tio_items *out)
{
    int from_stdin = !path || strcmp(path, "-") == 0;
    tio_items it = {from_stdin ? "<stdin>" : path, NULL, NULL, 0};
    FILE *fp = from_stdin ? stdin : fopen(path, "r");
    if (!fp) {
        fprintf(stderr, "garotor: %s: cannot open: %s\n", path, strerror(errno));
        return -1;
    }
    size_t vcap = 0, icap = 0, nval = 0;
    char *buf = NULL;
    size_t bufcap = 0;
    long lineno = 0;
    int status = 0;
    while (getline(&buf, &bufcap, fp) >= 0) {
        lineno++;
        if (lineno == 1 && skip_header)
            continue;
        char *s = buf;
        while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n')
            s++;
        if (*s == '\0' || *s == '#')
            continue;
        if (grow((void **)&it.item, &icap, it.n + 1, sizeof *it.item)) {
            fprintf(stderr, "garotor: %s:%ld: out of memory\n", it.name, lineno);
            status = -1;
            break;
        }
        tio_item *cur = &it.item[it.n++];
        cur->first = nval;
        cur->count = 0;
        cur->line = lineno;
        for (;;) {
            while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n' || *s == ',')
                s++;
            if (*s == '\0')
                break;
            char *end;
            errno = 0;
            double x = strtod(s, &end);
            if (end == s) {
                char tok[32];
                size_t k = strcspn(s, " \t\r\n,");
                if (k >= sizeof tok)
                    k = sizeof tok - 1;
                memcpy(tok, s, k);
                tok[k] = '\0';
                status = tio_error(&it, it.n - 1, "'%s' is not a number", tok);
                break;
            }
            if (!isfinite(x)) {
                status = tio_error(&it, it.n - 1, "number %d is not finite", cur->count + 1);
                break;
            }
            if (*end != '\0' && !strchr(" \t\r\n,", *end)) {
                status = tio_error(&it, it.n - 1, "junk after number %d", cur->count + 1);
                break;
            }
            if (grow((void **)&it.value, &vcap, nval + 1, sizeof *it.value)) {
                status = tio_error(&it, it.n - 1, "out of memory");
                break;
            }
            it.value[nval++] = x;
            cur->count++;
            s = end;
        }
        if (status)
            break;
    }
    if (status == 0 && ferror(fp)) {
        fprintf(stderr, "garotor: %s: read error\n", it.name);
        status = -1;
    }
    free(buf);
    if (!from_stdin)
        fclose(fp);
    if (status) {
        tio_free(&it);
        return -1;
    }
    *out = it;
    return 0;
}

int tio_out_open(tio_out *o, const char *path)
{
    memset(o, 0, sizeof *o);
    if (!path || strcmp(path, "-") == 0) {
        o->fp = stdout;
        return 0;
    }
    o->path = path;
    if (snprintf(o->tmp, sizeof o->tmp, "%s.tmpXXXXXX", path) >= (int)sizeof o->tmp) {
        fprintf(stderr, "garotor: %s: name too long\n", path);
        return -1;
    }
    int fd = mkstemp(o->tmp);
    if (fd < 0 || !(o->fp = fdopen(fd, "w"))) {
        fprintf(stderr, "garotor: %s: cannot write: %s\n", path, strerror(errno));
        if (fd >= 0) {
            close(fd);
            unlink(o->tmp);
        }
        return -1;
    }
    return 0;
}

void tio_out_line(tio_out *o, const double *v, int n)
{
    for (int i = 0; i < n; i++)
        fprintf(o->fp, i ? " %.17g" : "%.17g", v[i] == 0.0 ? 0.0 : v[i]);
    fputc('\n', o->fp);
}

int tio_out_close(tio_out *o, int ok)
{
    if (!o->fp)
        return ok ? 0 : -1;
    int werr = fflush(o->fp) != 0 || ferror(o->fp);
    if (!o->path) {
        o->fp = NULL;
        if (werr) {
            fprintf(stderr, "garotor: <stdout>: write error\n");
            return -1;
        }
        return ok ? 0 : -1;
    }
    werr |= fclose(o->fp) != 0;
    o->fp = NULL;
    if (ok && !werr && rename(o->tmp, o->path) == 0)
        return 0;
    if (ok)
        fprintf(stderr, "garotor: %s: cannot write: %s\n", o->path, strerror(errno));
    unlink(o->tmp);
    return -1;
}
