/* Compiled as C: uses nothing but runtime/ramus_runtime.h, so it proves the header is valid C
 * and that ramus_runtime links on its own. Usage: c_api_smoke GOOD.rmb TRUNCATED.rmb */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "runtime/ramus_runtime.h"

static char* read_all(const char* path, size_t* n) {
  FILE* f = fopen(path, "rb");
  char* data = NULL;
  long size;
  if (!f) return NULL;
  if (fseek(f, 0, SEEK_END) == 0 && (size = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0) {
    data = (char*)malloc((size_t)size + 1);
    if (data && fread(data, 1, (size_t)size, f) != (size_t)size) {
      free(data);
      data = NULL;
    }
    *n = (size_t)size;
  }
  fclose(f);
  return data;
}

/* Every parent precedes its child and every position is finite. */
static int check_skeleton(const ramus_skeleton* s) {
  size_t i, n = ramus_node_count(s);
  double p[3], r;
  if (n == 0) return 0;
  for (i = 0; i < n; ++i) {
    int64_t parent = ramus_node_parent(s, i);
    if (ramus_node_position(s, i, p) != 0 || ramus_node_radius(s, i, &r) != 0) return 0;
    if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]) || !(r >= 0)) return 0;
    if (parent >= (int64_t)i) return 0;
  }
  return ramus_node_position(s, n, p) == -1;
}

int main(int argc, char** argv) {
  char err[256];
  size_t n = 0;
  char* bytes;
  ramus_grammar* g;
  ramus_skeleton* s;
  int ok;
  if (argc != 3) return 2;
  bytes = read_all(argv[1], &n);
  if (!bytes) return 2;
  g = ramus_load(bytes, n, err, sizeof err);
  free(bytes);
  if (!g) {
    fprintf(stderr, "load: %s\n", err);
    return 1;
  }
  s = ramus_grow(g, -1, ramus_grammar_seed(g), err, sizeof err);
  if (!s) {
    fprintf(stderr, "grow: %s\n", err);
    ramus_free_grammar(g);
    return 1;
  }
  ok = check_skeleton(s);
  printf("%lu nodes, %lu organs\n", (unsigned long)ramus_node_count(s),
         (unsigned long)ramus_organ_count(s));
  ramus_free_skeleton(s);
  ramus_free_grammar(g);
  if (!ok) return 1;

  /* A truncated image: an error naming the byte offset, no grammar. */
  bytes = read_all(argv[2], &n);
  if (!bytes) return 2;
  g = ramus_load(bytes, n, err, sizeof err);
  free(bytes);
  if (g || strncmp(err, "byte ", 5) != 0) return 1;
  printf("truncated: %s\n", err);
  return 0;
}
