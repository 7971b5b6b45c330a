/* tools/textio.h: reading numbers and writing results for the garotor tool.
 *
 * Input (docs/tool.md): one item a line, numbers separated by whitespace or
 * commas; blank lines and lines starting with '#' are skipped; with --header
 * the first line is skipped too. Every number must be finite. The whole input
 * is read and checked before anything is written, so an error leaves neither
 * partial output on standard output nor an output file behind.
 *
 * Output: numbers as the shortest decimal that reads back as the same double
 * (numtext.h); to standard output, or to a temporary file beside --out that is
 * renamed onto it only when everything succeeded; the file keeps the mode of
 * the one it replaces (a new one gets 0666 less the umask), and a symbolic
 * link is followed, not replaced. An --out that exists and is not a regular
 * file (a FIFO, a terminal, /dev/null) is written in place.
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

/** Read every item of `path` (NULL or "-" for standard input). On error prints
 *  "garotor: FILE:LINE: what" to stderr and returns -1; 0 on success. */
int tio_read(const char *path, int skip_header, tio_items *out);
/** The same, also keeping the text of each item's first number (a time, read
 *  exactly from it: timetext.h) in out->first. */
int tio_read_first(const char *path, int skip_header, tio_items *out);
void tio_free(tio_items *items);

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
    char tmp[4096];   /* temporary name while writing */
} tio_out;

/** Open the output (path NULL or "-" for standard output). Returns 0 or -1 (message printed). */
int tio_out_open(tio_out *o, const char *path);
/** Write n numbers as one line, each the shortest decimal that reads back
 *  as it (numtext.h), a negative zero as 0. */
void tio_out_line(tio_out *o, const double *v, int n);
/** Write a time stamp (as text) and n numbers as one line, as above. */
void tio_out_stamped(tio_out *o, const char *stamp, const double *v, int n);
/** Finish: flush, and rename the temporary file onto the target when ok;
 *  when !ok remove it. Returns 0 or -1 (message printed). */
int tio_out_close(tio_out *o, int ok);
/** The whole output at once: n rows of `width` numbers (row after row in v),
 *  opened, written and closed as above. Returns 0 or -1 (message printed). */
int tio_write_rows(const char *path, const double *v, size_t n, int width);
/** Remove what a successful tio_out_open/close wrote to path: the regular
 *  file it names (through a symbolic link too), never a FIFO or a device. */
void tio_out_unwrite(const char *path);

#endif
