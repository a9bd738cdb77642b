/* Options files, checked before PetscInitialize (which reports an unreadable one with an error
   wall): every -options_file (or -options_file_yaml) on the command line, in PETSC_OPTIONS and,
   recursively, inside options files names a readable file. An options file is read as PETSc reads
   it: '#', '!' and '%' start a comment, the rest is a stream of whitespace-separated tokens.
   Nesting deeper than MAX_DEPTH (a file that names itself, directly or not) is an error too. A
   YAML file must be one PETSc can read (options-yaml.c). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <spcontact.h>

#define MAX_DEPTH 16 /* options files inside options files */
#define MAX_LINE  8192

typedef struct {
  int         loud;  /* this process prints the error (the first rank) */
  const char *from;  /* the file naming it (NULL: the command line or PETSC_OPTIONS) */
  int         depth; /* 0 on the command line */
} Where;

static int CheckFile(const char *opt, const char *file, const Where *w);

static int IsFileOption(const char *tok)
{
  return !strcmp(tok, "-options_file") || !strcmp(tok, "-options_file_yaml");
}

static int Fail(const Where *w, const char *opt, const char *file, const char *why)
{
  char in[PETSC_MAX_PATH_LEN + 32] = "";

  if (w->from) snprintf(in, sizeof(in), " (in %s)", w->from);
  if (w->loud) fprintf(stderr, "spcontact: error: %s %s%s: %s\n", opt, file, in, why);
  return 1;
}

/* One token of a stream: *pending is the file option the previous token was (its value follows) */
static int Token(const char *tok, const char **pending, const Where *w)
{
  if (*pending) {
    const char *opt = *pending;
    *pending        = NULL;
    return CheckFile(opt, tok, w);
  }
  if (IsFileOption(tok)) *pending = strcmp(tok, "-options_file") ? "-options_file_yaml" : "-options_file";
  return 0;
}

/* The next whitespace-separated token of *s (terminated in place), NULL at the end; reentrant,
   unlike strtok: a file's tokens are read while the files it names are */
static char *NextToken(char **s)
{
  char *tok = *s + strspn(*s, " \t\r\n");

  if (!*tok) return NULL;
  *s = tok + strcspn(tok, " \t\r\n");
  if (**s) *(*s)++ = 0;
  return tok;
}

/* The tokens of an options file, comments removed, checked in order */
static int CheckContents(FILE *fp, const Where *w)
{
  char        line[MAX_LINE];
  const char *pending = NULL;

  while (fgets(line, sizeof(line), fp)) {
    char *rest = line, *tok;
    line[strcspn(line, "#!%")] = 0;
    while ((tok = NextToken(&rest)))
      if (Token(tok, &pending, w)) return 1;
  }
  if (pending && w->loud) fprintf(stderr, "spcontact: error: %s at the end of %s needs a file name\n", pending, w->from);
  return pending ? 1 : 0;
}

static int CheckFile(const char *opt, const char *file, const Where *w)
{
  Where inner = *w;
  FILE *fp;
  int   bad;

  if (w->depth >= MAX_DEPTH) return Fail(w, opt, file, "options files nested more than 16 deep (does a file name itself?)");
  errno = 0;
  fp    = fopen(file, "r");
  if (!fp) {
    char why[256];
    snprintf(why, sizeof(why), "cannot read the file (%s); check the path", strerror(errno ? errno : ENOENT));
    return Fail(w, opt, file, why);
  }
  inner.from  = file;
  inner.depth = w->depth + 1;
  if (!strcmp(opt, "-options_file")) bad = CheckContents(fp, &inner);
  else {
    char why[512];
    bad = SPCheckYAMLStream(fp, why, sizeof(why));
    if (bad) Fail(w, opt, file, why);
  }
  fclose(fp);
  return bad;
}

/* The PETSC_OPTIONS environment variable: a token stream like an options file's */
static int CheckEnvironment(const Where *w)
{
  const char *env = getenv("PETSC_OPTIONS");
  char        copy[MAX_LINE], *rest = copy, *tok;
  const char *pending = NULL;

  if (!env) return 0;
  snprintf(copy, sizeof(copy), "%s", env);
  while ((tok = NextToken(&rest)))
    if (Token(tok, &pending, w)) return 1;
  if (pending && w->loud) fprintf(stderr, "spcontact: error: %s at the end of PETSC_OPTIONS needs a file name\n", pending);
  return pending ? 1 : 0;
}

int SPCheckOptionsFiles(int argc, char **argv)
{
  const char *rank = getenv("OMPI_COMM_WORLD_RANK") ? getenv("OMPI_COMM_WORLD_RANK") : getenv("PMI_RANK");
  Where       w    = {!rank || !strcmp(rank, "0"), NULL, 0};

  for (int i = 1; i < argc; ++i) {
    if (!IsFileOption(argv[i])) continue;
    if (i + 1 >= argc) {
      if (w.loud) fprintf(stderr, "spcontact: error: %s needs a file name\n", argv[i]);
      return 1;
    }
    if (CheckFile(argv[i], argv[i + 1], &w)) return 1;
  }
  return CheckEnvironment(&w);
}
