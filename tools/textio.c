/* tools/textio.c: see textio.h. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "textio.h"

#include <garotor/numtext.h>

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static int grow(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return 0;
    size_t c = *cap ? *cap : 64;
    while (c < need) c *= 2;
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
    if (items->first)
        for (size_t i = 0; i < items->n; i++) free(items->first[i]);
    free(items->first);
    free(items->value);
    free(items->item);
    memset(items, 0, sizeof *items);
}

static int read_items(const char *path, int skip_header, int keep_first, tio_items *out)
{
    int from_stdin = !path || strcmp(path, "-") == 0;
    tio_items it = {from_stdin ? "<stdin>" : path, NULL, NULL, 0, NULL};
    size_t fcap = 0;
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
        /* a UTF-8 byte-order mark (spreadsheets and Windows editors write
           one) is no character of the data */
        if (lineno == 1 && strncmp(s, "\xEF\xBB\xBF", 3) == 0)
            s += 3;
        while (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n') s++;
        if (*s == '\0' || *s == '#')
            continue;
        if (grow((void **)&it.item, &icap, it.n + 1, sizeof *it.item)) {
            fprintf(stderr, "garotor: %s:%ld: out of memory\n", it.name, lineno);
            status = -1;
            break;
        }
        if (keep_first && grow((void **)&it.first, &fcap, it.n + 1, sizeof *it.first)) {
            fprintf(stderr, "garotor: %s:%ld: out of memory\n", it.name, lineno);
            status = -1;
            break;
        }
        if (keep_first)
            it.first[it.n] = NULL;
        tio_item *cur = &it.item[it.n++];
        cur->first = nval;
        cur->count = 0;
        cur->line = lineno;
        /* Between two numbers: whitespace, or one comma with optional
         * whitespace around it. A comma with no number on one side of it is an
         * empty CSV field ("1,,2", ",1", "1,"): an error, never skipped, so a
         * missing value cannot shift the ones after it. */
        for (;;) {
            int comma = 0;
            for (;; s++) {
                if (*s == ',' && (comma || cur->count == 0)) {
                    status = cur->count ? tio_error(&it, it.n - 1, "empty field after number %d", cur->count)
                                        : tio_error(&it, it.n - 1, "empty field before number 1");
                    break;
                }
                if (*s == ',')
                    comma = 1;
                else if (*s != ' ' && *s != '\t' && *s != '\r' && *s != '\n')
                    break;
            }
            if (status)
                break;
            if (*s == '\0') {
                if (comma)
                    status = tio_error(&it, it.n - 1, "empty field after number %d", cur->count);
                break;
            }
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
            if (keep_first && cur->count == 0) {
                const char *w = s;
                while (*w == ' ' || *w == '\t' || *w == '\r' || *w == '\n' || *w == '\f' || *w == '\v') w++;
                char *t = malloc((size_t)(end - w) + 1);
                if (!t) {
                    status = tio_error(&it, it.n - 1, "out of memory");
                    break;
                }
                memcpy(t, w, (size_t)(end - w));
                t[end - w] = '\0';
                it.first[it.n - 1] = t;
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

int tio_read(const char *path, int skip_header, tio_items *out)
{
    return read_items(path, skip_header, 0, out);
}

int tio_read_first(const char *path, int skip_header, tio_items *out)
{
    return read_items(path, skip_header, 1, out);
}

/* Temporaries being written (at most --out, --svg and --html at once): a
 * SIGINT, SIGTERM or SIGHUP removes them before the tool dies of it, so an
 * interrupted run leaves no FILE.tmpXXXXXX behind. unlink, signal and raise
 * are async-signal-safe; a slot is cleared only after its file was renamed
 * or removed, so the handler at worst unlinks a name that is gone. */
#define TIO_PENDING 4
static char *volatile tio_pending[TIO_PENDING];

static void tio_on_signal(int sig)
{
    for (int i = 0; i < TIO_PENDING; i++)
        if (tio_pending[i])
            unlink(tio_pending[i]);
    signal(sig, SIG_DFL);
    raise(sig);
}

static void tio_pend(char *tmp, int on)
{
    static int installed;
    if (on && !installed) {
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = tio_on_signal;
        sigemptyset(&sa.sa_mask);
        const int sigs[3] = {SIGINT, SIGTERM, SIGHUP};
        for (int i = 0; i < 3; i++) {
            struct sigaction old;
            /* a signal the caller ignores (nohup) stays ignored */
            if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
                sigaction(sigs[i], &sa, NULL);
        }
        installed = 1;
    }
    for (int i = 0; i < TIO_PENDING; i++)
        if (on ? !tio_pending[i] : tio_pending[i] == tmp) {
            tio_pending[i] = on ? tmp : NULL;
            return;
        }
}

static void tio_out_release(tio_out *o)
{
    free(o->resolved);
    o->resolved = NULL;
}

int tio_out_open(tio_out *o, const char *path)
{
    memset(o, 0, sizeof *o);
    if (!path || strcmp(path, "-") == 0) {
        o->fp = stdout;
        return 0;
    }
    o->path = path;
    /* A symbolic link is followed, so that the file it names is replaced and
     * the link stays a link. */
    struct stat st;
    int exists = stat(path, &st) == 0;
    if (exists && !S_ISREG(st.st_mode)) {
        /* a FIFO, a terminal or a device such as /dev/null: written in place,
         * never replaced by a regular file */
        o->direct = 1;
        if (!(o->fp = fopen(path, "w"))) {
            fprintf(stderr, "garotor: %s: cannot write: %s\n", path, strerror(errno));
            return -1;
        }
        return 0;
    }
    if (exists) {
        char *real = realpath(path, NULL);
        if (!real) {
            fprintf(stderr, "garotor: %s: cannot write: %s\n", path, strerror(errno));
            return -1;
        }
        o->path = o->resolved = real;
    }
    if (snprintf(o->tmp, sizeof o->tmp, "%s.tmpXXXXXX", o->path) >= (int)sizeof o->tmp) {
        fprintf(stderr, "garotor: %s: name too long\n", path);
        tio_out_release(o);
        return -1;
    }
    int fd = mkstemp(o->tmp);
    /* mkstemp creates the file private (0600); give it the mode the file it
     * replaces had, or that a new file gets (0666 less the umask) */
    mode_t mask = umask(0);
    umask(mask);
    mode_t mode = exists ? st.st_mode & 07777 : 0666 & ~mask;
    if (fd < 0 || fchmod(fd, mode) != 0 || !(o->fp = fdopen(fd, "w"))) {
        fprintf(stderr, "garotor: %s: cannot write: %s\n", path, strerror(errno));
        if (fd >= 0) {
            close(fd);
            unlink(o->tmp);
        }
        tio_out_release(o);
        return -1;
    }
    setvbuf(o->fp, NULL, _IOFBF, 1 << 16); /* a line is some 300 bytes: fewer writes */
    tio_pend(o->tmp, 1);
    return 0;
}

/* Numbers after the first column: each the shortest decimal that reads
 * back as it (numtext.h), a negative zero as 0; the line is built in a
 * buffer and written at once. */
static void put_numbers(tio_out *o, const char *lead, size_t llen, const double *v, int n)
{
    char line[4096];
    size_t k = 0;
    if (llen) {
        if (llen > sizeof line - 1 - GA_DOUBLE_TEXT_MAX) {
            fwrite(lead, 1, llen, o->fp);
        } else {
            memcpy(line, lead, llen);
            k = llen;
        }
    }
    for (int i = 0; i < n; i++) {
        if (k + GA_DOUBLE_TEXT_MAX + 2 > sizeof line) {
            fwrite(line, 1, k, o->fp);
            k = 0;
        }
        if (i || llen)
            line[k++] = ' ';
        k += ga_double_format(v[i] == 0.0 ? 0.0 : v[i], line + k);
    }
    line[k++] = '\n';
    fwrite(line, 1, k, o->fp);
}

void tio_out_stamped(tio_out *o, const char *stamp, const double *v, int n)
{
    put_numbers(o, stamp, strlen(stamp), v, n);
}

void tio_out_line(tio_out *o, const double *v, int n) { put_numbers(o, "", 0, v, n); }

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
    int rc = -1;
    if (o->direct) {
        if (werr)
            fprintf(stderr, "garotor: %s: write error\n", o->path);
        else
            rc = ok ? 0 : -1;
    } else if (ok && !werr && rename(o->tmp, o->path) == 0) {
        rc = 0;
        tio_pend(o->tmp, 0);
    } else {
        if (ok)
            fprintf(stderr, "garotor: %s: cannot write: %s\n", o->path, strerror(errno));
        unlink(o->tmp);
        tio_pend(o->tmp, 0);
    }
    tio_out_release(o);
    return rc;
}

void tio_out_unwrite(const char *path)
{
    char *real = realpath(path, NULL);
    struct stat st;
    if (real && stat(real, &st) == 0 && S_ISREG(st.st_mode))
        remove(real);
    free(real);
}

int tio_write_rows(const char *path, const double *v, size_t n, int width)
{
    tio_out out;
    if (tio_out_open(&out, path))
        return -1;
    for (size_t i = 0; i < n; i++) tio_out_line(&out, v + i * (size_t)width, width);
    return tio_out_close(&out, 1);
}
