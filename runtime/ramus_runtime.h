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

#ifdef __cplusplus
}
#endif

#endif /* RAMUS_RUNTIME_H */
