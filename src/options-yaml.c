/* A YAML options file (-options_file_yaml), checked before PetscInitialize as PETSc 3.18 reads it
   (src/sys/objects/optionsyaml.c), so that a file it would refuse with an error wall is reported
   in one line: the YAML parses (libyaml), and every document is empty or a mapping of scalar keys
   to scalars, sequences (of scalars or one-pair mappings) or mappings (prefixes); "<<" merges a
   mapping or a sequence of mappings; a key "$$..." is skipped, but with the tag !include its
   value names a YAML file read in place (checked the same way). A key given twice in one mapping
   (not valid YAML; libyaml keeps both and PETSc took the last without a word) is refused, and so
   is one option set twice in one file under two spellings, which PETSc also let the later
   override: keys that differ in case (PETSc's option names ignore it), or a nested key and the
   joined one (`contact: {method: alm}` and `contact_method: penalty`); a key taken from a "<<"
   merge may be overridden, as YAML means it to be. A key with a leading dash (`-contact_method`)
   is refused too: PETSc reads it as `--contact_method`, an option nothing reads, and the run took
   the default without a word until the unused-option report at its end (QA helper 30), and so is
   an empty key or one with a space (`contact method: alm`), which PETSc set as options nothing
   reads. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <yaml.h>

#define MAX_DEPTH 16 /* !include inside included files */
#define MAX_NAME  256

typedef struct {
  char          name[MAX_NAME]; /* the option as PETSc forms it, without the dash */
  unsigned long line;
} Seen;

typedef struct {
  yaml_document_t *doc;
  char            *why; /* the reason of a failure */
  size_t           len;
  int              depth;  /* of !include */
  char             prefix[MAX_NAME]; /* the nested keys joined with '_', as PETSc pushes them */
  int              merging; /* inside a "<<" merge: its keys may be overridden */
  Seen            *seen;    /* the options this file set, in order */
  size_t           nseen, maxseen;
} Ctx;

static int Layer(Ctx *c, yaml_node_t *node);
static int Stream(FILE *fp, int depth, char why[], size_t len);

static const char *Str(yaml_node_t *n)
{
  return (const char *)n->data.scalar.value;
}

static int Bad(Ctx *c, yaml_node_t *n, const char *what)
{
  snprintf(c->why, c->len, "line %lu: %s", n ? (unsigned long)n->start_mark.line + 1 : 0UL, what);
  return 1;
}

/* The option that key k sets (the prefix and k, as PETSc joins them), once per file: a second
   spelling of one already set is refused (PETSc's option names ignore case) */
static int Record(Ctx *c, yaml_node_t *k)
{
  char name[MAX_NAME], what[1024];

  if (Str(k)[0] == '-') {
    snprintf(what, sizeof(what), "key '%.100s': YAML keys are option names without the dash (PETSc would read it as -%.100s%.100s, an option nothing reads): write '%.100s'", Str(k), c->prefix, Str(k), Str(k) + 1);
    return Bad(c, k, what);
  }
  if (c->merging) return 0; /* a merged key: the mapping's own keys may override it */
  snprintf(name, sizeof(name), "%s%s", c->prefix, Str(k));
  for (size_t i = 0; i < c->nseen; ++i) {
    if (strcasecmp(c->seen[i].name, name)) continue;
    snprintf(what, sizeof(what), "option -%.100s set twice in this file (first as '%.100s' on line %lu%s): PETSc would let the later override the first without a word; keep one", name, c->seen[i].name, c->seen[i].line, strcmp(c->seen[i].name, name) ? ", and option names ignore case" : "; nested keys join with '_'");
    return Bad(c, k, what);
  }
  if (c->nseen == c->maxseen) {
    Seen *more = realloc(c->seen, (c->maxseen ? 2 * c->maxseen : 64) * sizeof(Seen));
    if (!more) return 0; /* no memory for the check: PETSc's reading is unchanged */
    c->seen = more, c->maxseen = c->maxseen ? 2 * c->maxseen : 64;
  }
  snprintf(c->seen[c->nseen].name, MAX_NAME, "%s", name);
  c->seen[c->nseen++].line = (unsigned long)k->start_mark.line + 1;
  return 0;
}

/* Layer under the prefix key_ (a mapping value, or a list item's pair) */
static int Nested(Ctx *c, yaml_node_t *k, yaml_node_t *node)
{
  const size_t n = strlen(c->prefix);
  int          bad;

  snprintf(c->prefix + n, sizeof(c->prefix) - n, "%s_", Str(k));
  bad = Layer(c, node);
  c->prefix[n] = 0;
  return bad;
}

/* A sequence item: a scalar, or a mapping of at most one pair (not a merge) read as a layer */
static int Item(Ctx *c, yaml_node_t *k0, yaml_node_t *it)
{
  yaml_node_pair_t *p;

  if (!it) return Bad(c, it, "corrupt YAML document");
  if (it->type == YAML_SCALAR_NODE) return 0;
  if (it->type != YAML_MAPPING_NODE) return Bad(c, it, "a list item must be a value or a 'key: value' pair");
  p = it->data.mapping.pairs.start;
  if (it->data.mapping.pairs.top - p > 1) return Bad(c, it, "a list item may hold one 'key: value' pair only");
  if (p < it->data.mapping.pairs.top) {
    yaml_node_t *k = yaml_document_get_node(c->doc, p->key);
    if (!k || k->type != YAML_SCALAR_NODE) return Bad(c, it, "an option name must be a plain word");
    if (!strcmp(Str(k), "<<")) return Bad(c, k, "the merge key '<<' is not accepted inside a list");
  }
  return Nested(c, k0, it);
}

/* A "<<" value: a mapping or a sequence of mappings */
static int Merge(Ctx *c, yaml_node_t *v)
{
  int bad = 0;

  if (v->type != YAML_MAPPING_NODE && v->type != YAML_SEQUENCE_NODE) return Bad(c, v, "'<<' needs a mapping or a list of mappings");
  c->merging++;
  if (v->type == YAML_MAPPING_NODE) bad = Layer(c, v);
  for (yaml_node_item_t *i = v->data.sequence.items.start; v->type == YAML_SEQUENCE_NODE && i < v->data.sequence.items.top && !bad; ++i) {
    yaml_node_t *m = yaml_document_get_node(c->doc, *i);
    if (!m || m->type != YAML_MAPPING_NODE) bad = Bad(c, v, "'<<' needs a mapping or a list of mappings");
    else bad = Layer(c, m);
  }
  c->merging--;
  return bad;
}

/* A "$$" key's value: with the tag !include, the YAML file it names */
static int Include(Ctx *c, yaml_node_t *v)
{
  const char *tag = (const char *)v->tag;
  size_t      n   = tag ? strlen(tag) : 0;
  char        inner[512];
  FILE       *fp;
  int         bad;

  if (n < 8 || strcmp(tag + n - 8, "!include") || v->type != YAML_SCALAR_NODE) return 0;
  if (!(fp = fopen(Str(v), "r"))) {
    snprintf(inner, sizeof(inner), "!include %s: cannot read the file; check the path", Str(v));
    return Bad(c, v, inner);
  }
  bad = Stream(fp, c->depth + 1, inner, sizeof(inner));
  fclose(fp);
  if (bad && strstr(inner, ": !include ")) snprintf(c->why, c->len, "%s", inner); /* the innermost file's failure */
  else if (bad) snprintf(c->why, c->len, "line %lu: !include %s: %s", (unsigned long)v->start_mark.line + 1, Str(v), inner);
  return bad;
}

/* One value of a key */
static int Value(Ctx *c, yaml_node_t *k, yaml_node_t *v)
{
  int bad = 0;

  if (!strcmp(Str(k), "<<")) return Merge(c, v);
  if (!strncmp(Str(k), "$$", 2)) return Include(c, v);
  if (!Str(k)[0] || strpbrk(Str(k), " \t")) { /* PETSc sets "-" or "-contact method", which nothing reads */
    char what[256];
    snprintf(what, sizeof(what), "key '%.100s': %s (PETSc would set an option nothing reads, and the run would go on without it)", Str(k), Str(k)[0] ? "an option name has no spaces: join its words with '_'" : "an empty key is not an option name");
    return Bad(c, k, what);
  }
  if (!strcmp(Str(k), "options_file") || !strcmp(Str(k), "options_file_yaml"))
    return Bad(c, k, "PETSc does not read an options file named inside a YAML file; give it on the command line, or include a YAML file with '$$name: !include file.yaml'");
  if (Str(k)[0] == '-' || v->type != YAML_MAPPING_NODE) bad = Record(c, k); /* a mapping sets no option of its own */
  if (!bad && v->type == YAML_MAPPING_NODE) return Nested(c, k, v);
  if (v->type == YAML_SEQUENCE_NODE)
    for (yaml_node_item_t *i = v->data.sequence.items.start; i < v->data.sequence.items.top && !bad; ++i) bad = Item(c, k, yaml_document_get_node(c->doc, *i));
  return bad;
}

static int Layer(Ctx *c, yaml_node_t *node)
{
  if (node->type != YAML_MAPPING_NODE) return Bad(c, node, "expected 'option: value' lines (a mapping), not a list or a bare value");
  for (yaml_node_pair_t *p = node->data.mapping.pairs.start; p < node->data.mapping.pairs.top; ++p) {
    yaml_node_t *k = yaml_document_get_node(c->doc, p->key), *v = yaml_document_get_node(c->doc, p->value);

    if (!k || !v) return Bad(c, node, "corrupt YAML document");
    if (k->type != YAML_SCALAR_NODE) return Bad(c, k, "an option name must be a plain word");
    for (yaml_node_pair_t *q = node->data.mapping.pairs.start; q < p; ++q) { /* libyaml keeps both; PETSc took the last */
      yaml_node_t *kq = yaml_document_get_node(c->doc, q->key);
      char         what[256];
      if (!kq || kq->type != YAML_SCALAR_NODE || strcmp(Str(kq), Str(k)) || !strcmp(Str(k), "<<")) continue;
      snprintf(what, sizeof(what), "'%.100s' given twice in one mapping (first on line %lu); YAML keys are unique, and PETSc would let the later one override the first without a word: keep one", Str(k), (unsigned long)kq->start_mark.line + 1);
      return Bad(c, k, what);
    }
    if (Value(c, k, v)) return 1;
  }
  return 0;
}

static int Stream(FILE *fp, int depth, char why[], size_t len)
{
  yaml_parser_t   parser;
  yaml_document_t doc;
  yaml_node_t    *root;
  Ctx             c   = {&doc, why, len, depth, "", 0, NULL, 0, 0};
  int             bad = 0;

  if (depth > MAX_DEPTH) return snprintf(why, len, "!include nested more than %d deep (does a file include itself?)", MAX_DEPTH), 1;
  if (!yaml_parser_initialize(&parser)) return snprintf(why, len, "the YAML parser cannot start"), 1;
  yaml_parser_set_input_file(&parser, fp);
  do {
    if (!yaml_parser_load(&parser, &doc)) {
      snprintf(why, len, "not valid YAML (line %lu, column %lu: %s)", (unsigned long)parser.problem_mark.line + 1, (unsigned long)parser.problem_mark.column + 1, parser.problem ? parser.problem : "parse error");
      bad = 1;
      break;
    }
    root = yaml_document_get_root_node(&doc);
    if (root) bad = Layer(&c, root);
    yaml_document_delete(&doc);
  } while (root && !bad);
  yaml_parser_delete(&parser);
  free(c.seen);
  return bad;
}

/* 0 if PETSc can read the stream fp as options; else 1 with the reason in why */
int SPCheckYAMLStream(FILE *fp, char why[], size_t len)
{
  return Stream(fp, 0, why, len);
}
