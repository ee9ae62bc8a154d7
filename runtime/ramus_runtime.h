/* The embeddable ramus runtime: load a binary grammar (.rmb, docs/binary-format.md), derive it
 * and run the turtle into a skeleton, from C or C++. Plain C89-compatible declarations; every
 * object is an opaque handle the caller frees. No function throws or aborts: a failure returns
 * NULL (or a negative status) and writes a NUL-terminated message into `err` (truncated to
 * `errlen` bytes; `err` may be NULL). See docs/runtime.md. */
#ifndef RAMUS_RUNTIME_H
#define RAMUS_RUNTIME_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ramus_grammar ramus_grammar;
typedef struct ramus_skeleton ramus_skeleton;

/* Decodes and verifies an .rmb image (the bytes are copied; the caller keeps them). A corrupted
 * or truncated image gives NULL and a message naming the byte offset and what was expected. */
ramus_grammar* ramus_load(const void* bytes, size_t n, char* err, size_t errlen);
void ramus_free_grammar(ramus_grammar* g);

/* The grammar's own `derive N` and `seed S`. */
int ramus_grammar_steps(const ramus_grammar* g);
uint64_t ramus_grammar_seed(const ramus_grammar* g);

/* Derives `steps` steps (-1: the grammar's `derive N`) with `seed` (pass
 * ramus_grammar_seed(g) for the grammar's own) and interprets the string with the turtle.
 * The result equals what `ramus build` grows from the source grammar with the same seed. */
ramus_skeleton* ramus_grow(const ramus_grammar* g, int steps, uint64_t seed, char* err,
                           size_t errlen);
void ramus_free_skeleton(ramus_skeleton* s);

/* Nodes: a forest; the segment of node i runs from its parent's position to its own. The
 * getters return 0, or -1 when i is out of range (outputs untouched). */
size_t ramus_node_count(const ramus_skeleton* s);
int ramus_node_position(const ramus_skeleton* s, size_t i, double xyz[3]);
int ramus_node_radius(const ramus_skeleton* s, size_t i, double* radius);
/* The parent's index, or -1 for a root (and for i out of range). */
int64_t ramus_node_parent(const ramus_skeleton* s, size_t i);

/* Organs (leaves, flowers) placed with `~`. */
size_t ramus_organ_count(const ramus_skeleton* s);
int ramus_organ_position(const ramus_skeleton* s, size_t i, double xyz[3]);
int ramus_organ_size(const ramus_skeleton* s, size_t i, double* size);

/* ---- Placed pieces (runtime/ramus_runtime_pieces.cpp) -------------------------------------
 * An .rmb built with `ramus build FILE --target binary --placed-pieces` carries trees of
 * interlocking pieces as a compact stream (section 12, docs/binary-format.md): per piece its
 * type, parent rim, twist and, where posed, quantized joint poses. ramus_pieces_expand turns it
 * into the pieces instance buffer (docs/instance-buffer.md): the same bytes `ramus build FILE
 * --target pieces --instance-buffer OUT.bin` writes for the same tree, and the same tables as
 * arrays. The piece meshes themselves are in that build's glTF. */

typedef struct ramus_pieces ramus_pieces;

/* One instance record (16 bytes, the file's layout): draw call per piece type. */
typedef struct ramus_piece_instance {
  uint32_t bone_offset; /* global index of its root-joint bone */
  uint32_t tile_offset; /* its first entry in ramus_pieces_tiles */
  uint32_t tree;
  uint16_t piece_type;
  uint16_t joints; /* its bones: bone_offset .. bone_offset + joints - 1 */
} ramus_piece_instance;

/* Decodes and verifies an .rmb image and expands its placed pieces. NULL with a message (the
 * byte offset and what was expected for a malformed stream) when the image is not a valid
 * .rmb or holds no placed pieces. */
ramus_pieces* ramus_pieces_expand(const void* rmb_bytes, size_t n, char* err, size_t errlen);
void ramus_free_pieces(ramus_pieces* p);

size_t ramus_pieces_type_count(const ramus_pieces* p);
size_t ramus_pieces_tree_count(const ramus_pieces* p);
size_t ramus_pieces_instance_count(const ramus_pieces* p);
size_t ramus_pieces_bone_count(const ramus_pieces* p);
size_t ramus_pieces_tile_count(const ramus_pieces* p);
/* Piece type t's name (NUL-terminated, owned by p), or NULL when t is out of range. */
const char* ramus_pieces_type_name(const ramus_pieces* p, size_t t);

/* The tables, owned by p (NULL when empty): per piece type its first instance and instance
 * count (2 values per type); instances sorted by piece type; per bone its skinning matrix, 16
 * floats column-major, y up like the glTF; per instance tile slices (one per base quad). */
const uint32_t* ramus_pieces_ranges(const ramus_pieces* p);
const ramus_piece_instance* ramus_pieces_instances(const ramus_pieces* p);
const float* ramus_pieces_bones(const ramus_pieces* p);
const uint16_t* ramus_pieces_tiles(const ramus_pieces* p);

/* The whole instance buffer file (little-endian), owned by p; its size in *size. */
const void* ramus_pieces_instance_buffer(const ramus_pieces* p, size_t* size);

#ifdef __cplusplus
}
#endif

#endif /* RAMUS_RUNTIME_H */
