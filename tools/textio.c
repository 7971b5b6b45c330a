/* tools/textio.c: see textio.h. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "textio.h"

#include <garotor/numtext.h>

#include <errno.h>
#include <fcntl.h>
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

/* The lines of one input, read a block at a time with read(2), so that a
 * line is held only up to the limit (an endless one, /dev/zero, costs the
 * limit and a block, never more) and a failure is never taken for the end of
 * the input. */
size_t tio_read_block = 1 << 16;
typedef struct {
    int fd;
    const char *name;
    size_t max;   /* the longest line, bytes before its newline */
    long lineno;  /* lines returned so far */
    char *line;   /* the current line, NUL-terminated, without its newline */
    size_t cap;   /* bytes at line: at most max + 1 */
    char *blk;    /* bytes read ahead */
    size_t blksz; /* bytes at blk */
    size_t pos, len;
    int eof;
} tio_lines;

/* The next line into r->line: 1, or 0 at the end of the input, or -1 after a
 * message (a read error, a NUL byte, a line longer than r->max, out of
 * memory), each naming the line (and for a NUL byte its column). */
static int next_line(tio_lines *r)
{
    size_t len = 0;
    int any = 0;
    long at = r->lineno + 1;
    for (;;) {
        if (r->pos == r->len) {
            if (r->eof)
                break;
            ssize_t k;
            do k = read(r->fd, r->blk, r->blksz);
            while (k < 0 && errno == EINTR);
            if (k < 0) {
                fprintf(stderr, "garotor: %s:%ld: read error: %s\n", r->name, at, strerror(errno));
                return -1;
            }
            if (k == 0) {
                r->eof = 1;
                break;
            }
            r->pos = 0;
            r->len = (size_t)k;
        }
        any = 1;
        const char *s = r->blk + r->pos, *nl = memchr(s, '\n', r->len - r->pos);
        size_t take = nl ? (size_t)(nl - s) : r->len - r->pos, room = r->max - len;
        /* in the order of the bytes: a NUL within the limit, else the byte
           past the limit */
        const char *z = memchr(s, '\0', take < room ? take : room);
        if (z) {
            fprintf(stderr,
                    "garotor: %s:%ld:%zu: NUL byte: not text (a binary file, or UTF-16: save it as UTF-8)\n",
                    r->name, at, len + (size_t)(z - s) + 1);
            return -1;
        }
        if (take > room) {
            fprintf(stderr, "garotor: %s:%ld: line longer than %zu bytes (--max-line N reads longer ones)\n",
                    r->name, at, r->max);
            return -1;
        }
        if (len + take + 1 > r->cap) {
            size_t c = r->cap < 256 ? 256 : r->cap <= r->max / 2 ? 2 * r->cap : r->max + 1;
            if (c < len + take + 1)
                c = len + take + 1;
            char *q = realloc(r->line, c);
            if (!q) {
                fprintf(stderr, "garotor: %s:%ld: out of memory\n", r->name, at);
                return -1;
            }
            r->line = q;
            r->cap = c;
        }
        memcpy(r->line + len, s, take);
        len += take;
        r->pos += take + (nl != NULL);
        if (nl)
            break;
    }
    if (!any)
        return 0;
    r->line[len] = '\0';
    r->lineno = at;
    return 1;
}

static int read_items(const char *path, const tio_read_opts *ro, int keep_first, tio_items *out)
{
    int from_stdin = !path || strcmp(path, "-") == 0;
    tio_items it = {from_stdin ? "<stdin>" : path, NULL, NULL, 0, NULL};
    size_t fcap = 0;
    tio_lines r = {.fd = from_stdin ? 0 : open(path, O_RDONLY),
                   .name = it.name,
                   .max = ro->max_line ? ro->max_line : TIO_MAX_LINE,
                   .blksz = tio_read_block ? tio_read_block : 1};
    if (r.fd < 0) {
        fprintf(stderr, "garotor: %s: cannot open: %s\n", path, strerror(errno));
        return -1;
    }
    size_t vcap = 0, icap = 0, nval = 0;
    int status = 0, got;
    if (!(r.blk = malloc(r.blksz))) {
        fprintf(stderr, "garotor: %s:1: out of memory\n", it.name);
        status = -1;
    }
    while (status == 0 && (got = next_line(&r)) != 0) {
        if (got < 0) {
            status = -1;
            break;
        }
        long lineno = r.lineno;
        if (lineno == 1 && ro->header)
            continue;
        char *s = r.line;
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
                /* a header line (a CSV's column names, a word first) where
                   --header would skip it */
                int header = lineno == 1 && ro->can_header && cur->count == 0;
                status = tio_error(&it, it.n - 1, "'%s' is not a number%s", tok,
                                   header ? ": is this a header line? pass --header" : "");
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
    free(r.line);
    free(r.blk);
    if (!from_stdin)
        close(r.fd);
    if (status) {
        tio_free(&it);
        return -1;
    }
    *out = it;
    return 0;
}

void tio_texts_free(tio_texts *t)
{
    for (size_t i = 0; i < t->n; i++) free(t->text[i]);
    free(t->text);
    free(t->line);
    free(t->col);
    memset(t, 0, sizeof *t);
}

int tio_text_error(const tio_texts *t, size_t i, size_t at, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "garotor: %s:%ld:%zu: ", t->name, t->line[i], t->col[i] + at);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return -1;
}

/* raw: every line that is not blank, comments and a header included, as
   it is (tio_read_lines); else the lines tio_read_text keeps, trimmed */
static int read_text(const char *path, const tio_read_opts *ro, int raw, tio_texts *out)
{
    int from_stdin = !path || strcmp(path, "-") == 0;
    tio_texts t = {from_stdin ? "<stdin>" : path, NULL, NULL, NULL, 0};
    tio_lines r = {.fd = from_stdin ? 0 : open(path, O_RDONLY),
                   .name = t.name,
                   .max = ro->max_line ? ro->max_line : TIO_MAX_LINE,
                   .blksz = tio_read_block ? tio_read_block : 1};
    if (r.fd < 0) {
        fprintf(stderr, "garotor: %s: cannot open: %s\n", path, strerror(errno));
        return -1;
    }
    size_t cap[3] = {0, 0, 0};
    int status = 0, got;
    if (!(r.blk = malloc(r.blksz))) {
        fprintf(stderr, "garotor: %s:1: out of memory\n", t.name);
        status = -1;
    }
    while (status == 0 && (got = next_line(&r)) != 0) {
        if (got < 0) {
            status = -1;
            break;
        }
        if (r.lineno == 1 && ro->header && !raw)
            continue;
        char *s = r.line;
        if (r.lineno == 1 && strncmp(s, "\xEF\xBB\xBF", 3) == 0)
            s += 3;
        if (raw ? s[strspn(s, " \t\r\n")] == '\0' : (s += strspn(s, " \t\r\n"), *s == '\0' || *s == '#'))
            continue;
        size_t len = strlen(s);
        while (!raw && len && strchr(" \t\r\n", s[len - 1])) len--;
        char *copy = malloc(len + 1);
        if (!copy || grow((void **)&t.text, &cap[0], t.n + 1, sizeof *t.text) ||
            grow((void **)&t.line, &cap[1], t.n + 1, sizeof *t.line) ||
            grow((void **)&t.col, &cap[2], t.n + 1, sizeof *t.col)) {
            free(copy);
            fprintf(stderr, "garotor: %s:%ld: out of memory\n", t.name, r.lineno);
            status = -1;
            break;
        }
        memcpy(copy, s, len);
        copy[len] = '\0';
        t.text[t.n] = copy;
        t.line[t.n] = r.lineno;
        t.col[t.n] = (size_t)(s - r.line) + 1;
        t.n++;
    }
    free(r.line);
    free(r.blk);
    if (!from_stdin)
        close(r.fd);
    if (status) {
        tio_texts_free(&t);
        return -1;
    }
    *out = t;
    return 0;
}

int tio_read_text(const char *path, const tio_read_opts *ro, tio_texts *out)
{
    return read_text(path, ro, 0, out);
}

int tio_read_lines(const char *path, const tio_read_opts *ro, tio_lines_text *out)
{
    return read_text(path, ro, 1, out);
}

int tio_read(const char *path, const tio_read_opts *ro, tio_items *out)
{
    return read_items(path, ro, 0, out);
}

int tio_read_first(const char *path, const tio_read_opts *ro, tio_items *out)
{
    return read_items(path, ro, 1, out);
}

/* Temporaries being written (at most --out, --svg and --html at once): any
 * signal whose default action ends the process removes them before it dies
 * of it, so a killed run leaves no FILE.tmpXXXXXX behind: POSIX's signals
 * that terminate (with or without a core), the real-time ones included, and
 * Linux's SIGPWR and SIGSTKFLT; not SIGKILL, which cannot be caught. The handler goes only where the default
 * action is: a signal the caller ignores (nohup) stays ignored, and one a
 * sanitizer or a fuzzer handles (ASan's SIGSEGV, libFuzzer's SIGALRM) stays
 * theirs. unlink, signal and raise are async-signal-safe; a slot is set and
 * cleared with the signals blocked, when its file was created, renamed or
 * removed, so the handler never misses a temporary nor unlinks another's. */
#define TIO_PENDING 4
static char *volatile tio_pending[TIO_PENDING];

static const int tio_signals[] = {
    SIGHUP,    SIGINT,  SIGQUIT, SIGILL,  SIGTRAP, SIGABRT, SIGBUS, SIGFPE,    SIGUSR1, SIGSEGV,
    SIGUSR2,   SIGPIPE, SIGALRM, SIGTERM, SIGXCPU, SIGXFSZ, SIGSYS, SIGVTALRM, SIGPROF,
#ifdef SIGPOLL
    SIGPOLL,
#endif
#ifdef SIGPWR /* Linux's own, which end the process too */
    SIGPWR,
#endif
#ifdef SIGSTKFLT
    SIGSTKFLT,
#endif
};

static void tio_on_signal(int sig)
{
    for (int i = 0; i < TIO_PENDING; i++)
        if (tio_pending[i])
            unlink(tio_pending[i]);
    /* then the default action, at once: sig unblocked and raised again
       (raised while blocked, it would wait for the handler's return, which
       valgrind loses in a blocking call) */
    signal(sig, SIG_DFL);
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, sig);
    sigprocmask(SIG_UNBLOCK, &one, NULL);
    raise(sig);
}

/* Install the handler on every signal whose action is the default one. */
static void tio_handle_signals(void)
{
    struct sigaction sa, old;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = tio_on_signal;
    sigfillset(&sa.sa_mask); /* one handler at a time */
    int nsig = (int)(sizeof tio_signals / sizeof tio_signals[0]), last = 0;
#ifdef SIGRTMIN
    last = SIGRTMAX - SIGRTMIN + 1; /* the real-time signals, after the others */
#endif
    for (int i = 0; i < nsig + last; i++) {
        int sig = i < nsig ? tio_signals[i] : 0;
#ifdef SIGRTMIN
        if (i >= nsig)
            sig = SIGRTMIN + (i - nsig);
#endif
        if (sigaction(sig, NULL, &old) == 0 && !(old.sa_flags & SA_SIGINFO) && old.sa_handler == SIG_DFL)
            sigaction(sig, &sa, NULL);
    }
}

/* Block every signal (*saved: the mask before), or restore the mask. */
static void tio_block(sigset_t *saved, int on)
{
    sigset_t all;
    sigfillset(&all);
    sigprocmask(on ? SIG_BLOCK : SIG_SETMASK, on ? &all : saved, on ? saved : NULL);
}

/* Record (on) or forget o's temporary; called with the signals blocked. */
static void tio_pend(tio_out *o, int on)
{
    static int installed;
    if (on && !installed) {
        tio_handle_signals();
        installed = 1;
    }
    for (int i = 0; i < TIO_PENDING; i++)
        if (on ? !tio_pending[i] : tio_pending[i] == o->tmp) {
            tio_pending[i] = on ? o->tmp : NULL;
            break;
        }
    o->pending = on;
}

/* Remove o's temporary file, if there is one. */
static void tio_unlink_tmp(tio_out *o)
{
    if (!o->pending)
        return;
    sigset_t saved;
    tio_block(&saved, 1);
    unlink(o->tmp);
    tio_pend(o, 0);
    tio_block(&saved, 0);
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
    /* created and recorded with the signals blocked: no moment when the file
       exists and a signal would leave it */
    sigset_t saved;
    tio_block(&saved, 1);
    int fd = mkstemp(o->tmp);
    if (fd >= 0)
        tio_pend(o, 1);
    tio_block(&saved, 0);
    /* mkstemp creates the file private (0600); give it the mode the file it
     * replaces had, or that a new file gets (0666 less the umask) */
    mode_t mask = umask(0);
    umask(mask);
    mode_t mode = exists ? st.st_mode & 07777 : 0666 & ~mask;
    if (fd < 0 || fchmod(fd, mode) != 0 || !(o->fp = fdopen(fd, "w"))) {
        fprintf(stderr, "garotor: %s: cannot write: %s\n", path, strerror(errno));
        if (fd >= 0)
            close(fd);
        tio_unlink_tmp(o);
        tio_out_release(o);
        return -1;
    }
    setvbuf(o->fp, NULL, _IOFBF, 1 << 16); /* a line is some 300 bytes: fewer writes */
    return 0;
}

/* Numbers after the first column: each the shortest decimal that reads
 * back as it (numtext.h), a negative zero as 0; the line is built in a
 * buffer and written at once. */
static void put_numbers(tio_out *o, const char *lead, size_t llen, const double *v, int n)
{
    char line[4096], sep = o->sep ? o->sep : ' ';
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
            line[k++] = sep;
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

void tio_out_text(tio_out *o, const char *text, size_t len)
{
    fwrite(text, 1, len, o->fp);
    fputc('\n', o->fp);
}

int tio_out_finish(tio_out *o)
{
    if (!o->fp)
        return 0;
    int werr = fflush(o->fp) != 0 || ferror(o->fp);
    if (!o->path) {
        o->fp = NULL;
        if (werr) {
            fprintf(stderr, "garotor: <stdout>: write error\n");
            return -1;
        }
        return 0;
    }
    werr |= fclose(o->fp) != 0;
    o->fp = NULL;
    if (!werr)
        return 0;
    if (o->direct)
        fprintf(stderr, "garotor: %s: write error\n", o->path);
    else
        fprintf(stderr, "garotor: %s: cannot write: %s\n", o->path, strerror(errno));
    tio_unlink_tmp(o);
    tio_out_release(o);
    return -1;
}

int tio_out_commit(tio_out *o)
{
    int rc = 0;
    if (o->pending) {
        sigset_t saved;
        tio_block(&saved, 1);
        if (rename(o->tmp, o->path) == 0) {
            tio_pend(o, 0);
        } else {
            rc = -1;
            fprintf(stderr, "garotor: %s: cannot write: %s\n", o->path, strerror(errno));
            unlink(o->tmp);
            tio_pend(o, 0);
        }
        tio_block(&saved, 0);
    }
    tio_out_release(o);
    return rc;
}

void tio_out_discard(tio_out *o)
{
    if (o->fp && o->path)
        fclose(o->fp);
    o->fp = NULL;
    tio_unlink_tmp(o);
    tio_out_release(o);
}

int tio_out_close(tio_out *o, int ok)
{
    if (ok)
        return tio_out_finish(o) == 0 && tio_out_commit(o) == 0 ? 0 : -1;
    /* what was written to standard output or a device stays written: its
       write error is still told */
    if (!o->path || o->direct)
        tio_out_finish(o);
    tio_out_discard(o);
    return -1;
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
