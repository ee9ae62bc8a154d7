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

/* ramus_grow keeps the string buffers of its derivation (from 64 KB; those from 2 MB resident
 * while later grows keep taking them, given back lazily after a second unused) so that the next
 * grow writes to pages it already has. A client done growing trees for a while calls this to
 * give them all back to the system; it returns their bytes (0 when nothing was kept). */
size_t ramus_release_memory(void);

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

/* ==== Mesher ==================================================================================
 * The tree mesh `ramus build` writes, built here by the same code (mesh/, docs/mesh.md): bark
 * tubes, leaf cards and the turtle's polygons, for each level of detail, as arrays a renderer
 * uploads directly; plus the turtle frames and branch orders a caller needs to place its own
 * geometry. Implemented in runtime/ramus_mesher.cpp; see docs/runtime.md, "Meshes". */

/* The turtle frame at node i (ABOP: heading H, left L, up U; orthonormal, H x L = U) in the
 * skeleton's frame (z up, like ramus_node_position). Each output may be NULL. 0, or -1 when i is
 * out of range. */
int ramus_node_frame(const ramus_skeleton* s, size_t i, double heading[3], double left[3],
                     double up[3]);
/* Branch order of node i: 0 the trunk, +1 per lateral branch; -1 when i is out of range. */
int ramus_node_order(const ramus_skeleton* s, size_t i);
/* The frame of organ i: a leaf card lies along its heading, across its left. As above. */
int ramus_organ_frame(const ramus_skeleton* s, size_t i, double heading[3], double left[3],
                      double up[3]);
/* The node organ i hangs from, or -1 (none, or i out of range). */
int64_t ramus_organ_node(const ramus_skeleton* s, size_t i);

typedef struct ramus_mesh ramus_mesh;

/* What `ramus build` takes on its command line for a mesh, with its defaults from
 * ramus_mesh_options_init. */
typedef struct ramus_mesh_options {
  int lod_count;        /* levels LOD0 .. LOD(lod_count-1), 1..8 (`--lod lod_count-1`) */
  double pipe_exponent; /* 0: radii from the turtle's widths; >= 1: the pipe model
                           (`--pipe-exponent`) */
  int crossed_leaves;   /* 0: one card per leaf; 1: two crossed cards (`--leaves crossed`) */
  double leaf_scale;    /* leaf length per unit of organ size, > 0 (`--leaf-scale`) */
  int y_up;             /* 1: glTF's frame, (x, y, z) -> (x, z, -y): the .glb's arrays; 0: z up */
} ramus_mesh_options;

/* The defaults of `ramus build`: 1 level, the turtle's radii, one card per leaf, scale 1, y up. */
void ramus_mesh_options_init(ramus_mesh_options* o);

/* Meshes a skeleton (NULL options: the defaults). With the same grammar, seed and options the
 * arrays equal, bit for bit, the accessors of the .glb `ramus build` writes (y_up = 1). NULL and
 * a message for invalid options or a skeleton that cannot be meshed. */
ramus_mesh* ramus_mesh_build(const ramus_skeleton* s, const ramus_mesh_options* o, char* err,
                             size_t errlen);
void ramus_free_mesh(ramus_mesh* m);

/* The number of levels (0 for NULL). */
int ramus_mesh_lod_count(const ramus_mesh* m);
/* Where the vertices' (0, 0, 0) lies in the world, in the mesh's frame: (0, 0, 0) for a tree
 * near the origin, a local origin for a georeferenced one (docs/mesh.md). 0, or -1 for NULL. */
int ramus_mesh_origin(const ramus_mesh* m, double xyz[3]);

/* The parts of a level, the glTF's primitives: each has its own vertices and material. */
#define RAMUS_PART_BARK 0     /* "bark": opaque, with tangents for its normal map */
#define RAMUS_PART_LEAVES 1   /* "leaf": alpha-masked cards, 4 vertices per face (UVs 0..1) */
#define RAMUS_PART_SURFACES 2 /* "surface": the turtle's polygons, front and back faces */

/* Counts of part `part` of level `lod`: 0 for an empty part and for lod or part out of range. */
size_t ramus_mesh_vertex_count(const ramus_mesh* m, int lod, int part);
size_t ramus_mesh_index_count(const ramus_mesh* m, int lod, int part); /* 3 per triangle */

/* The arrays of a part, owned by the mesh and valid until ramus_free_mesh; NULL for an empty
 * part and for lod or part out of range. */
const float* ramus_mesh_positions(const ramus_mesh* m, int lod, int part); /* 3 per vertex */
const float* ramus_mesh_normals(const ramus_mesh* m, int lod, int part);   /* 3 per vertex, unit */
const float* ramus_mesh_uvs(const ramus_mesh* m, int lod, int part);       /* 2 per vertex */
/* 4 per vertex (glTF TANGENT: xyz the direction of growing u, w = +-1); bark only, else NULL. */
const float* ramus_mesh_tangents(const ramus_mesh* m, int lod, int part);
/* 4 per vertex (glTF _WIND): x main bend (0 at the base, 1 at the top), y branch bend (0 where a
 * branch leaves its parent, 1 at its tip), z phase in [0, 1) per branch, w leaf flutter. */
const float* ramus_mesh_wind(const ramus_mesh* m, int lod, int part);
/* 1 per vertex: the skeleton node whose motion the vertex follows (UINT32_MAX: none). */
const uint32_t* ramus_mesh_skin_nodes(const ramus_mesh* m, int lod, int part);
/* Triangles, counter-clockwise seen from outside. */
const uint32_t* ramus_mesh_indices(const ramus_mesh* m, int lod, int part);

/* ==== end of the mesher ====================================================================== */
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
