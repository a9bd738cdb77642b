/* Options files, checked before PetscInitialize (which reports an unreadable one with an error
   wall): every -options_file (or -options_file_yaml) on the command line, in PETSC_OPTIONS and,
   recursively, inside options files names a readable file. An options file is read as PETSc reads
   it: '#', '!' and '%' start a comment, the rest is a stream of whitespace-separated tokens.
   Nesting deeper than MAX_DEPTH (a file that names itself, directly or not) is an error too, and so
   is a line PETSc's reader refuses (two values, two options). A YAML file must be one PETSc can
   read (options-yaml.c). */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
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

/* PETSc's option name test (PetscOptionsValidKey): a dash, a letter, and not a number (-inf) */
static int ValidKey(const char *key)
{
  char *end;

  if (!key || key[0] != '-') return 0;
  if (key[1] == '-') key++;
  if (!isalpha((unsigned char)key[1])) return 0;
  (void)strtod(key, &end);
  return end == key || *end == '_' || isalnum((unsigned char)*end);
}

/* Up to max tokens of a line as PETSc splits it (PetscTokenFind with ' '): a token that starts
   with '"' runs to the next '"'; *n the count (max + 1: more) */
static void LineTokens(char *s, char *tok[], int max, int *n)
{
  *n = 0;
  while (*s == ' ') s++;
  while (*s && *n <= max) {
    const char end = *s == '"' ? '"' : ' ';
    if (end == '"') s++;
    if (*n < max) tok[*n] = s;
    (*n)++;
    while (*s && *s != end) s++;
    if (*s) *s++ = 0;
    while (*s == ' ') s++;
  }
}

/* One line as PETSc's options-file reader takes it (PetscOptionsInsertFilePetsc: '#' comments,
   tabs and CRs as spaces; an option and at most one value, or "alias -a -b"); what it refuses with
   an error wall is said here in one line */
static int CheckLine(const char *text, int number, const Where *w)
{
  char  line[MAX_LINE], *tok[4], why[MAX_LINE + 64] = "";
  int   n, alias;

  if (number == 1 && !strncmp(text, "\xef\xbb\xbf", 3)) { /* PETSc would read it as part of the first token */
    if (w->loud) fprintf(stderr, "spcontact: error: %s starts with a UTF-8 byte-order mark (written by some editors), which PETSc reads as part of its first line; save it without one (sed -i '1s/^\\xEF\\xBB\\xBF//' %s)\n", w->from, w->from);
    return 1;
  }
  snprintf(line, sizeof(line), "%s", text);
  line[strcspn(line, "#")] = 0;
  for (char *c = line; *c; ++c)
    if (*c == '\t' || *c == '\r' || *c == '\n') *c = ' ';
  LineTokens(line, tok, 4, &n);
  if (!n) return 0;
  alias = !strcasecmp(tok[0], "alias");
  if (tok[0][0] == '-' && !ValidKey(tok[0])) snprintf(why, sizeof(why), "%s is not an option name (a dash and a letter)", tok[0]);
  else if (tok[0][0] != '-' && !alias) snprintf(why, sizeof(why), "the line starts with %s, not an option name", tok[0]);
  else if (!alias && n > 1 && ValidKey(tok[1])) snprintf(why, sizeof(why), "two options on one line (%s %s)", tok[0], tok[1]);
  else if (!alias && n > 2 && ValidKey(tok[2])) snprintf(why, sizeof(why), "two options on one line (%s %s %s)", tok[0], tok[1], tok[2]);
  else if (n > (alias ? 3 : 2)) snprintf(why, sizeof(why), "%s has more than one value (%s ...)", alias ? "alias" : tok[0], tok[alias ? 3 : 2]);
  if (!why[0]) return 0;
  if (w->loud) fprintf(stderr, "spcontact: error: %s line %d: %s; an options file takes one option per line with at most one value (a value with spaces in double quotes: -bc_1_value \"0.0015, 0.001\")\n", w->from, number, why);
  return 1;
}

/* The tokens of an options file, comments removed, checked in order */
static int CheckContents(FILE *fp, const Where *w)
{
  char        line[MAX_LINE];
  const char *pending = NULL;
  int         number = 0;

  while (fgets(line, sizeof(line), fp)) {
    char *rest = line, *tok;
    if (CheckLine(line, ++number, w)) return 1;
    line[strcspn(line, "#!%")] = 0;
    while ((tok = NextToken(&rest)))
      if (Token(tok, &pending, w)) return 1;
  }
  if (pending && w->loud) fprintf(stderr, "spcontact: error: %s at the end of %s needs a file name\n", pending, w->from);
  return pending ? 1 : 0;
}

/* Whether path names a directory (fopen opens one for reading, and its reads fail) */
static int IsDirectory(const char *path)
{
  struct stat st;

  return !stat(path, &st) && S_ISDIR(st.st_mode);
}

static int CheckFile(const char *opt, const char *file, const Where *w)
{
  Where inner = *w;
  FILE *fp;
  int   bad;

  if (w->depth >= MAX_DEPTH) return Fail(w, opt, file, "options files nested more than 16 deep (does a file name itself?)");
  if (IsDirectory(file)) return Fail(w, opt, file, "a directory, not a file; give the options file's path");
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
