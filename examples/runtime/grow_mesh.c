/* grow_mesh: a tree from a binary grammar, grown and meshed by ramus_runtime alone (the C API of
 * runtime/ramus_runtime.h, no other library), the way a game or a web client would do it.
 *
 *   grow_mesh IN.rmb [OUT_DIR] [--seed S] [--lod N] [--leaves quad|crossed] [--leaf-scale K]
 *             [--pipe-exponent E] [--z-up] [--repeat R]
 *
 * The options are `ramus build`'s for a mesh. With OUT_DIR it writes every array of every level
 * and part as raw little-endian data, one file each, named after the glTF attribute the same
 * array has in the .glb `ramus build` writes (tests/runtime/test_grow_mesh_example.cpp compares
 * them byte for byte):
 *
 *   OUT_DIR/lod<k>_<bark|leaf|surface>_<POSITION|NORMAL|TEXCOORD_0|TANGENT|_WIND>.bin  (float32)
 *   OUT_DIR/lod<k>_<bark|leaf|surface>_indices.bin                                    (uint32)
 *
 * It prints the tree's size and the time to grow and to mesh it (the fastest of R runs). Exit
 * status: 0, or 1 with a message on stderr. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "runtime/ramus_runtime.h"

static const char* const kPartNames[3] = {"bark", "leaf", "surface"};

static int fail(const char* what, const char* why) {
  fprintf(stderr, "grow_mesh: %s: %s\n", what, why);
  return 1;
}

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* The whole file, or NULL with errno set. */
static unsigned char* read_file(const char* path, size_t* n) {
  FILE* f = fopen(path, "rb");
  unsigned char* bytes = NULL;
  size_t cap = 0;
  *n = 0;
  if (!f) return NULL;
  for (;;) {
    size_t got;
    if (*n == cap) {
      unsigned char* grown = realloc(bytes, cap ? 2 * cap : 65536);
      if (!grown) {
        free(bytes);
        fclose(f);
        errno = ENOMEM;
        return NULL;
      }
      bytes = grown;
      cap = cap ? 2 * cap : 65536;
    }
    got = fread(bytes + *n, 1, cap - *n, f);
    *n += got;
    if (got == 0) break;
  }
  if (ferror(f)) {
    free(bytes);
    fclose(f);
    errno = EIO;
    return NULL;
  }
  fclose(f);
  return bytes;
}

/* Writes `n` bytes to DIR/NAME through a temporary beside it renamed into place, so a reader
 * never sees half a file. 0, or 1 after a message. */
static int write_array(const char* dir, const char* name, const void* data, size_t n) {
  char path[4096], tmp[4104];
  FILE* f;
  if (snprintf(path, sizeof path, "%s/%s", dir, name) >= (int)sizeof path)
    return fail(name, "output path too long");
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  f = fopen(tmp, "wb");
  if (!f) return fail(tmp, strerror(errno));
  if ((n > 0 && fwrite(data, 1, n, f) != n) | (fclose(f) != 0)) {
    remove(tmp);
    return fail(tmp, "write failed");
  }
  if (rename(tmp, path) != 0) {
    remove(tmp);
    return fail(path, strerror(errno));
  }
  return 0;
}

static int write_mesh(const ramus_mesh* m, const char* dir) {
  int lod, part;
  for (lod = 0; lod < ramus_mesh_lod_count(m); ++lod) {
    for (part = 0; part < 3; ++part) {
      const size_t v = ramus_mesh_vertex_count(m, lod, part);
      char name[64];
      int bad = 0;
      if (ramus_mesh_index_count(m, lod, part) == 0) continue; /* the glTF has no primitive */
#define ARRAY(attribute, getter, per_vertex)                                        \
  snprintf(name, sizeof name, "lod%d_%s_%s.bin", lod, kPartNames[part], attribute); \
  bad = bad || write_array(dir, name, getter(m, lod, part), v * (per_vertex) * sizeof(float));
      ARRAY("POSITION", ramus_mesh_positions, 3)
      ARRAY("NORMAL", ramus_mesh_normals, 3)
      ARRAY("TEXCOORD_0", ramus_mesh_uvs, 2)
      if (ramus_mesh_tangents(m, lod, part)) {
        ARRAY("TANGENT", ramus_mesh_tangents, 4)
      }
      ARRAY("_WIND", ramus_mesh_wind, 4)
#undef ARRAY
      snprintf(name, sizeof name, "lod%d_%s_indices.bin", lod, kPartNames[part]);
      bad = bad || write_array(dir, name, ramus_mesh_indices(m, lod, part),
                               ramus_mesh_index_count(m, lod, part) * sizeof(uint32_t));
      if (bad) return 1;
    }
  }
  return 0;
}

static int parse_number(const char* flag, const char* text, double lo, double hi, double* out) {
  char* end = NULL;
  errno = 0;
  *out = strtod(text, &end);
  if (errno != 0 || end == text || *end != '\0' || !(*out >= lo && *out <= hi))
    return fail(flag, "expected a number in range");
  return 0;
}

int main(int argc, char** argv) {
  const char* in = NULL;
  const char* out_dir = NULL;
  ramus_mesh_options options;
  uint64_t seed = 0;
  int has_seed = 0, repeat = 1, i, r, part, lod, status = 0;
  double x, best_grow = 1e300, best_mesh = 1e300;
  unsigned char* bytes;
  size_t n;
  char err[512];
  ramus_grammar* g;
  ramus_skeleton* s = NULL;
  ramus_mesh* m = NULL;

  ramus_mesh_options_init(&options);
  for (i = 1; i < argc; ++i) {
    const char* a = argv[i];
    const int has_value = i + 1 < argc;
    if (strcmp(a, "--z-up") == 0) {
      options.y_up = 0;
    } else if (a[0] == '-' && a[1] == '-' && !has_value) {
      return fail(a, "needs a value");
    } else if (strcmp(a, "--seed") == 0) {
      char* end = NULL;
      errno = 0;
      seed = strtoull(argv[++i], &end, 10);
      if (errno != 0 || *end != '\0' || argv[i][0] == '-') return fail(a, "expected a seed");
      has_seed = 1;
    } else if (strcmp(a, "--lod") == 0) {
      if (parse_number(a, argv[++i], 0, 7, &x)) return 1;
      options.lod_count = (int)x + 1;
    } else if (strcmp(a, "--leaves") == 0) {
      ++i;
      if (strcmp(argv[i], "quad") != 0 && strcmp(argv[i], "crossed") != 0)
        return fail(a, "expected quad or crossed");
      options.crossed_leaves = strcmp(argv[i], "crossed") == 0;
    } else if (strcmp(a, "--leaf-scale") == 0) {
      if (parse_number(a, argv[++i], 1e-9, 1e9, &options.leaf_scale)) return 1;
    } else if (strcmp(a, "--pipe-exponent") == 0) {
      if (parse_number(a, argv[++i], 1, 10, &options.pipe_exponent)) return 1;
    } else if (strcmp(a, "--repeat") == 0) {
      if (parse_number(a, argv[++i], 1, 1000, &x)) return 1;
      repeat = (int)x;
    } else if (a[0] == '-') {
      return fail(a, "unknown option");
    } else if (!in) {
      in = a;
    } else if (!out_dir) {
      out_dir = a;
    } else {
      return fail(a, "one input and one output folder only");
    }
  }
  if (!in) {
    fprintf(stderr,
            "usage: grow_mesh IN.rmb [OUT_DIR] [--seed S] [--lod N] [--leaves quad|crossed] "
            "[--leaf-scale K] [--pipe-exponent E] [--z-up] [--repeat R]\n");
    return 1;
  }

  bytes = read_file(in, &n);
  if (!bytes) return fail(in, strerror(errno));
  g = ramus_load(bytes, n, err, sizeof err);
  free(bytes);
  if (!g) return fail(in, err);
  if (!has_seed) seed = ramus_grammar_seed(g);

  for (r = 0; r < repeat && status == 0; ++r) {
    double t0, t1, t2;
    ramus_free_mesh(m);
    ramus_free_skeleton(s);
    m = NULL;
    t0 = now_ms();
    s = ramus_grow(g, -1, seed, err, sizeof err);
    t1 = now_ms();
    if (s) m = ramus_mesh_build(s, &options, err, sizeof err);
    t2 = now_ms();
    if (!s || !m) {
      status = fail(in, err);
      break;
    }
    if (t1 - t0 < best_grow) best_grow = t1 - t0;
    if (t2 - t1 < best_mesh) best_mesh = t2 - t1;
  }

  if (status == 0) {
    printf("%s: %zu nodes, %zu organs;", in, ramus_node_count(s), ramus_organ_count(s));
    for (lod = 0; lod < ramus_mesh_lod_count(m); ++lod) {
      size_t vertices = 0, triangles = 0;
      for (part = 0; part < 3; ++part) {
        vertices += ramus_mesh_vertex_count(m, lod, part);
        triangles += ramus_mesh_index_count(m, lod, part) / 3;
      }
      printf(" LOD%d %zu vertices %zu triangles;", lod, vertices, triangles);
    }
    printf(" grow %.3f ms, mesh %.3f ms\n", best_grow, best_mesh);
    if (out_dir) status = write_mesh(m, out_dir);
  }
  ramus_free_mesh(m);
  ramus_free_skeleton(s);
  ramus_free_grammar(g);
  return status;
}
