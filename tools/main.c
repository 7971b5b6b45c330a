/* tools/main.c: the garotor command line: dispatch, options, help.
 * The reference for every command and option is docs/tool.md. */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    const char *name;
    int (*run)(const cli_opts *o);
    unsigned accepts; /* OPT_* bits */
    const char *help;
} command;

static const command commands[] = {
    {"demo", cmd_demo, OPT_SVG,
     "usage: garotor [demo] [--svg FILE]\n"
     "Run the built-in demonstration and print a short report.\n"
     "  --svg FILE   also draw it as an SVG picture\n"},
};

static const char usage[] =
    "usage: garotor [COMMAND] [OPTIONS]\n"
    "Rigid motions in conformal geometric algebra G(4,1).\n"
    "\n"
    "commands:\n"
    "  demo     (the default) the built-in demonstration\n"
    "\n"
    "garotor COMMAND --help shows a command's options.\n";

static const struct {
    const char *name;
    unsigned bit;
    int takes_value;
} option_table[] = {
    {"--in", OPT_IN, 1}, {"--out", OPT_OUT, 1}, {"--header", OPT_HEADER, 0},
    {"--group", OPT_GROUP, 1}, {"--scheme", OPT_SCHEME, 1}, {"--samples", OPT_SAMPLES, 1},
    {"--at", OPT_AT, 1}, {"--format", OPT_FORMAT, 1}, {"--eval", OPT_EVAL, 1},
    {"--step", OPT_STEP, 1}, {"--v0", OPT_V0, 6}, {"--velocities", OPT_VELOCITIES, 1},
    {"--svg", OPT_SVG, 1}, {"--view", OPT_VIEW, 1},
};

static int usage_error(const char *cmd, const char *what, const char *arg)
{
    fprintf(stderr, "garotor %s: %s%s%s\n(garotor %s --help shows the options)\n", cmd, what,
            arg ? ": " : "", arg ? arg : "", cmd);
    return 2;
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

static int parse_options(const command *c, int argc, char **argv, cli_opts *o)
{
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        size_t k = 0, nopt = sizeof option_table / sizeof option_table[0];
        while (k < nopt && strcmp(a, option_table[k].name) != 0)
            k++;
        if (k == nopt || !(c->accepts & option_table[k].bit))
            return usage_error(c->name, "unknown option", a);
        if (i + option_table[k].takes_value >= argc)
            return usage_error(c->name, "missing value for", a);
        const char *v = argv[i + 1];
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
        case OPT_VIEW: o->view = v; break;
        case OPT_SAMPLES: {
            char *end;
            errno = 0;
            o->samples = strtol(v, &end, 10);
            if (end == v || *end || errno || o->samples < 2)
                return usage_error(c->name, "--samples needs a whole number >= 2, not", v);
            break;
        }
        case OPT_STEP:
            if (parse_double(v, &o->step) || !(o->step > 0.0))
                return usage_error(c->name, "--step needs a number > 0, not", v);
            break;
        case OPT_V0:
            for (int j = 0; j < 6; j++)
                if (parse_double(argv[i + 1 + j], &o->v0[j]))
                    return usage_error(c->name, "--v0 needs 6 finite numbers, not", argv[i + 1 + j]);
            break;
        }
        i += option_table[k].takes_value;
    }
    return 0;
}

int main(int argc, char **argv)
{
    const command *c = &commands[0]; /* no arguments: the demonstration */
    int first = 1;
    if (argc > 1 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
        fputs(usage, stdout);
        return 0;
    }
    if (argc > 1 && argv[1][0] != '-') {
        size_t k = 0, ncmd = sizeof commands / sizeof commands[0];
        while (k < ncmd && strcmp(argv[1], commands[k].name) != 0)
            k++;
        if (k == ncmd) {
            fprintf(stderr, "garotor: unknown command '%s'\n%s", argv[1], usage);
            return 2;
        }
        c = &commands[k];
        first = 2;
    }
    for (int i = first; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(c->help, stdout);
            return 0;
        }
    cli_opts o;
    memset(&o, 0, sizeof o);
    int st = parse_options(c, argc - first, argv + first, &o);
    return st ? st : c->run(&o);
}
