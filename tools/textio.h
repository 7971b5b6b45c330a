/* tools/textio.h: reading numbers and writing results for the garotor tool.
 *
 * Input (docs/tool.md): one item a line, numbers separated by whitespace or
 * commas; blank lines and lines starting with '#' are skipped; with --header
 * the first line is skipped too. Every number must be finite. The whole input
 * is read and checked before anything is written, so an error leaves neither
 * partial output on standard output nor an output file behind. The reader
 * tells the end of the input from a failure to read it: a read error, a NUL
 * byte, a line longer than --max-line and a failed allocation are errors
 * naming the line, never an early end. A line is held only up to the limit:
 * memory stays bounded whatever the input (/dev/zero, a file with no newline).
 *
 * Output: numbers as the shortest decimal that reads back as the same double
 * (numtext.h); to standard output, or to a temporary file beside --out that is
 * renamed onto it only when everything succeeded; the file keeps the mode of
 * the one it replaces (a new one gets 0666 less the umask), and a symbolic
 * link is followed, not replaced. An --out that exists and is not a regular
 * file (a FIFO, a terminal, /dev/null) is written in place. A temporary file
 * is removed when the process is killed by any signal whose default action
 * ends it (tio_out_open installs the handlers, over the default action only:
 * a signal ignored, or handled by a sanitizer or a fuzzer, is left alone).
 */
#ifndef GAROTOR_TOOLS_TEXTIO_H
#define GAROTOR_TOOLS_TEXTIO_H

#include <stddef.h>
#include <stdio.h>

/** One item: `count` numbers starting at value[first], read from line `line`. */
typedef struct {
    size_t first;
    int count;
    long line;
} tio_item;

/** The items of one input. */
typedef struct {
    const char *name; /* file name for messages ("<stdin>" for standard input) */
    double *value;    /* all numbers, item after item */
    tio_item *item;
    size_t n;     /* number of items */
    char **first; /* tio_read_first: the text of each item's first number
                     (NULL for an item of none); else NULL */
} tio_items;

/** The default of --max-line: the longest line read, in bytes before its
 *  newline (1 MiB: a pose is some 150 bytes, a 32-number rotor 800). */
#define TIO_MAX_LINE ((size_t)1 << 20)
/** The largest --max-line accepted. */
#define TIO_MAX_LINE_MAX ((size_t)-1 / 4)

/** Bytes asked of each read(2) of an input: 65536. fuzz/fuzz_tool.c makes
 *  it a few bytes, so that its short inputs cross reads as long ones do. */
extern size_t tio_read_block;

/** How an input is read. */
typedef struct {
    int header;      /* skip the first line (--header) */
    int can_header;  /* --header applies to this input: a first line that is
                        not numbers names it in its message */
    size_t max_line; /* the longest line, in bytes before its newline
                        (--max-line; 0: TIO_MAX_LINE); a longer one is an error */
} tio_read_opts;

/** Read every item of `path` (NULL or "-" for standard input). On error prints
 *  "garotor: FILE:LINE: what" (a NUL byte: "FILE:LINE:COLUMN: ...") to stderr
 *  and returns -1; 0 on success. */
int tio_read(const char *path, const tio_read_opts *ro, tio_items *out);
/** The same, also keeping the text of each item's first number (a time, read
 *  exactly from it: timetext.h) in out->first. */
int tio_read_first(const char *path, const tio_read_opts *ro, tio_items *out);
void tio_free(tio_items *items);

/** The lines of one input as text (multivectors written with blade names,
 *  mvtext.h): every line the reader keeps (not blank, not a '#' line, not the
 *  first with --header), from its first non-blank byte, without its newline
 *  and trailing blanks (a '\r' included), a UTF-8 byte-order mark dropped. */
typedef struct {
    const char *name; /* file name for messages ("<stdin>" for standard input) */
    char **text;
    long *line;
    size_t *col; /* the byte column (from 1) of text[i][0] in its line */
    size_t n;
} tio_texts;

/** Read every kept line of `path` (NULL or "-": standard input) as text,
 *  with the checks of tio_read (NUL bytes, --max-line, read errors). 0, or
 *  -1 after a message. */
int tio_read_text(const char *path, const tio_read_opts *ro, tio_texts *out);
void tio_texts_free(tio_texts *t);
/** The lines of an input as they are (for a reader of named columns): every
 *  line that is not blank, comments ('#') and a header included, without its
 *  newline (a UTF-8 byte-order mark at the start dropped), read as
 *  tio_read_text reads; freed by tio_texts_free. */
typedef tio_texts tio_lines_text;
int tio_read_lines(const char *path, const tio_read_opts *ro, tio_lines_text *out);
/** Print "garotor: FILE:LINE:COLUMN: message" for line i, at byte `at` of
 *  its text, to stderr; returns -1. */
int tio_text_error(const tio_texts *t, size_t i, size_t at, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/** Print "garotor: FILE:LINE: message" for item i to stderr; returns -1. */
int tio_error(const tio_items *items, size_t i, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/** An output in progress. */
typedef struct {
    FILE *fp;
    const char *path; /* final name, NULL for standard output */
    char *resolved;   /* the file a symbolic link at path names (allocated) */
    int direct;       /* path is not a regular file (a FIFO, /dev/null): written in place */
    int pending;      /* tmp exists: removed on a signal until renamed or removed */
    char sep;         /* between numbers: ' ' when 0 (set it after tio_out_open: ',' for CSV) */
    char tmp[4096];   /* temporary name while writing */
} tio_out;
/* A tio_out that was never opened (all zero: TIO_OUT_NONE) may be given to
 * tio_out_commit and tio_out_discard, which do nothing with it. */
#define TIO_OUT_NONE                                                                                         \
    {                                                                                                        \
        0                                                                                                    \
    }

/** Open the output (path NULL or "-" for standard output). Returns 0 or -1 (message printed). */
int tio_out_open(tio_out *o, const char *path);
/** Write n numbers as one line, each the shortest decimal that reads back
 *  as it (numtext.h), a negative zero as 0. */
void tio_out_line(tio_out *o, const double *v, int n);
/** Write len bytes of text and a newline. */
void tio_out_text(tio_out *o, const char *text, size_t len);
/** Write a time stamp (as text) and n numbers as one line, as above. */
void tio_out_stamped(tio_out *o, const char *stamp, const double *v, int n);
/** Finish: flush, and rename the temporary file onto the target when ok;
 *  when !ok remove it. Returns 0 or -1 (message printed). */
int tio_out_close(tio_out *o, int ok);
/** Finish writing, but leave a regular file under its temporary name, to be
 *  renamed by tio_out_commit once whatever must come with it was written too
 *  (a picture with its samples); a signal still removes it. 0, or -1 after a
 *  message (a write error; the temporary file removed). */
int tio_out_finish(tio_out *o);
/** Rename a finished output onto its target (nothing for standard output, a
 *  device or a FIFO). 0, or -1 after a message (the temporary file removed). */
int tio_out_commit(tio_out *o);
/** Give up an output: close it and remove its temporary file, silently. */
void tio_out_discard(tio_out *o);
/** The whole output at once: n rows of `width` numbers (row after row in v),
 *  opened, written and closed as above. Returns 0 or -1 (message printed). */
int tio_write_rows(const char *path, const double *v, size_t n, int width);
/** Remove what a successful tio_out_open/close wrote to path: the regular
 *  file it names (through a symbolic link too), never a FIFO or a device. */
void tio_out_unwrite(const char *path);

#endif
