// The pieces back end's data model: trees assembled from a few instanceable quad-mesh pieces
// whose rims interlock, each rigged with a small skeleton (Burkus, Karpati & Szecsi, "Animated
// Trees with Interlocking Pieces", 2017: section 4 and the tile assignment of 5.1).
//
//   ast::Pieces --lower_pieces--> PieceSet (piece types: meshes at several LODs, rims, joints;
//                                           attach rules, root, twist, depth)
//   PieceSet --assemble / fit_skeleton--> Tree (placed pieces, one bone buffer, tiles)
//   Tree --random_pose / wind_clip--> bone locals;  --skin--> world vertices
//
// Conventions. Units are the grammar's; z is up. The canonical root rim of every piece is a
// regular hexagon of circumradius 1 in the plane z = 0, centred at the origin, corner k at angle
// 60k degrees about +z; the piece grows towards +z. A rim's building transform maps the canonical
// root rim onto that rim (corner k onto the rim's corner k), so the six twists of a joint are
// rotations by 60 * twist degrees about the rim axis. Every rim's vertex normals are those of a
// cone of the universal aperture kRimConeSlope, carried by the building transform, so normals
// match across a joint.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/similarity.h"
#include "core/skeleton.h"
#include "core/vec3.h"
#include "grammar/diagnostic.h"
#include "grammar/loader.h"
#include "grammar/source.h"

namespace ramus::pieces {

inline constexpr std::uint32_t kNone = 0xffffffffu;
inline constexpr int kRimCorners = 6;
// tan of the angle between a rim's outward surface normal and the plane of the rim: the quad
// loop next to every rim lies on a cone that narrows at this slope towards the piece's interior
// (section 4.4: "a cone surface with a universally fixed aperture angle").
inline constexpr double kRimConeSlope = 0.08;

// ---- piece types ----------------------------------------------------------------------------

enum class PieceKind : std::uint8_t { Tube, Fork, Trifurcation, Attachment, Mesh };

// One level of detail of a piece: a quad mesh in the piece's model space.
struct PieceMesh {
  int segments = 1;  // tessellation level: every base quad edge split into this many
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // unit
  std::vector<std::array<float, 2>> uvs;
  // Joint indices LOCAL to the piece (into PieceType::joints) and their weights: at most 4
  // non-zero, summing to 1; unused slots have joint 0 and weight 0.
  std::vector<std::array<std::uint16_t, 4>> joints;
  std::vector<std::array<float, 4>> weights;
  std::vector<std::array<std::uint32_t, 4>> quads;  // counter-clockwise seen from outside
  std::vector<std::uint8_t> quad_tile_type;         // 1 (tube) or 2 (near a fork), per quad
  std::vector<std::uint32_t> quad_source;           // the base (segments 1) quad it came from
  // Per rim (0 = root rim, 1 + i = leaves[i]): the vertices along the rim, 6 * segments of them,
  // starting at corner 0 and going through corners 1, 2, ... in order.
  std::vector<std::vector<std::uint32_t>> rim_loops;
};

struct Rim {
  std::string name;                      // "root", or the leaf rim's name ("top", "left", ...)
  Trs building;                          // canonical root rim -> this rim; identity for the root
  std::array<std::uint32_t, 6> corners;  // base-mesh (lods[0]) vertex of corner k
  std::uint16_t joint = 0;               // the joint its vertices are bound to with weight 1
};

struct Joint {
  std::string name;              // "root" or "rim:<leaf name>"
  std::uint32_t parent = kNone;  // local joint index; kNone for the root joint
  Trs bind_local;                // relative to the parent joint (piece space for the root)
  Mat4 bind;                     // bind pose in piece space
  Mat4 inverse_bind;             // inverse of `bind`
};

struct PieceType {
  std::string name;  // as declared: `piece Y = fork(...)` -> "Y"
  PieceKind kind = PieceKind::Tube;
  Rim root;                 // building = identity, joint 0
  std::vector<Rim> leaves;  // in the kind's rim order (tube: top; fork: left, right; ...)
  // joints[0] is the root joint at the root-rim centre (identity bind pose); joints[1 + i] is
  // the terminal joint of leaves[i], bound at leaves[i].building.
  std::vector<Joint> joints;
  std::vector<PieceMesh> lods;  // lods[0] is the base quad mesh; segments grow with the index
  double tube_length = 0;       // distance root rim -> farthest leaf rim centre (for fitting)

  // Index into `leaves` of the rim with that name, or kNone.
  std::uint32_t leaf_index(std::string_view rim_name) const;
};

// ---- a lowered pieces block -----------------------------------------------------------------

struct AttachTarget {
  std::uint32_t piece = 0;  // index into PieceSet::types
  double weight = 1.0;      // > 0; a target without a weight weighs 1
};
struct AttachRule {
  std::uint32_t piece = 0;  // the parent piece type
  std::uint32_t leaf = 0;   // its leaf rim (index into PieceType::leaves)
  std::vector<AttachTarget> targets;
};

struct PieceSet {
  std::string name;  // the block's name
  std::vector<PieceType> types;
  std::vector<AttachRule> rules;  // at most one per (piece, leaf)
  std::uint32_t root = 0;         // root piece type
  bool twist_any = true;          // `twist any;` (also the default): a seeded twist per joint
  int twist = 0;                  // `twist k;` 0..5: the same twist at every joint
  int depth = 8;                  // `depth D;`: the deepest piece (the root piece has depth 0)
  double rim_radius = 1.0;        // `rim hexagon(radius: r)`: world size of the root rim
  std::vector<int> lod_segments;  // the `segments` of each PieceType::lods entry

  // The rule for (piece, leaf) or nullptr: a leaf rim without a rule stays open (a branch tip).
  const AttachRule* rule(std::uint32_t piece, std::uint32_t leaf) const;
  std::uint32_t find(std::string_view piece_name) const;  // kNone when absent
};

struct LowerPiecesOptions {
  std::string block;  // the pieces block; empty: the first one of the root file
  std::vector<std::pair<std::string, double>> defines;  // -D name=value, params only
  std::vector<int> lod_segments{1, 2, 4};               // tessellation levels built per piece
  // Mesh files held in memory, by the name a mesh("NAME") piece gives: the files an .rmb embeds
  // (formats/rmb/rmb_pieces.h). Such a piece is read from these bytes, not from the disk.
  std::vector<std::pair<std::string, std::string>> mesh_files;
};

// A problem outside the source (no such block, unreadable mesh file, a mesh without rims) or a
// piece that cannot be built; the message names the file and place when there is one.
struct PiecesError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Lowers a checked program's pieces block: folds arguments, builds every piece type (built-in
// kinds parametrically, mesh("file") from glTF/OBJ relative to the declaring file) and its LODs.
// Problems located in the source go to `diagnostics` (check has_errors()); others throw.
PieceSet lower_pieces(const Program& program, const SourceManager& sources,
                      const LowerPiecesOptions& options, DiagnosticSink& diagnostics);

// True when the root file's chosen pieces block has no attach rules: such a block is fitted to
// the skeleton grown from the file's lsystem block instead of being assembled from rules.
bool pieces_block_fits_skeleton(const Program& program, std::string_view block);

// The lsystem the chosen pieces block names with `skeleton NAME;` (in the root file or an
// imported one), or an empty string: then the root file's first lsystem block.
std::string pieces_skeleton_system(const Program& program, std::string_view block);

// ---- assembled trees ------------------------------------------------------------------------

struct PlacedPiece {
  std::uint32_t type = 0;         // index into PieceSet::types
  std::uint32_t parent = kNone;   // index into Tree::pieces
  std::uint32_t parent_leaf = 0;  // the parent's leaf rim it hangs from
  std::uint8_t twist = 0;         // 0..5: rotation by 60 * twist degrees about the rim axis
  std::uint32_t depth = 0;        // 0 for the root piece
  // Piece space -> world in the rest pose: the world matrix of the piece's root bone. From attach
  // rules that is parent's topological x building x twist (section 4.2), with the tree's
  // placement as the root piece's; a fitted tree's terminal joints carry the fit instead of the
  // bare building transform.
  Mat4 topological;
  std::uint32_t bone_offset = 0;     // its joints are Tree::bones[bone_offset + local joint]
  std::vector<std::uint16_t> tiles;  // per base quad: texture-array slice (section 5.1)
};

struct Bone {
  std::uint32_t parent = kNone;  // index into Tree::bones
  std::uint32_t piece = 0;       // the placed piece owning it
  std::uint16_t joint = 0;       // its local joint index in that piece
  Trs rest;                      // local transform in the rest (topological) pose
};

struct Tree {
  std::vector<PlacedPiece> pieces;  // parents before children
  std::vector<Bone> bones;          // parents before children; bone i's parent < i
  // Posed local transform per bone (== rest unless posed or fitted); what a glTF node holds.
  std::vector<Trs> pose;
};

struct TileOptions {
  // Tiles available per tile type (index 0 -> type 1, index 1 -> type 2). The texture array
  // holds type 1's tiles at slices [0, n1) and type 2's at [n1, n1 + n2).
  std::array<std::uint16_t, 2> tiles_per_type{4, 2};
};

struct AssembleOptions {
  std::uint64_t seed = 0;
  std::uint32_t max_pieces = 100'000;  // stops growth (breadth first) beyond this many
  Trs placement;                       // rest local of the root bone: the tree in the world
  TileOptions tiles;
};

// A tree from the attach rules (section 4.2): the root piece, then at every leaf rim with a
// rule one target drawn by weight, breadth first down to depth `depth`; a twist per joint
// (seeded when `twist any`). Topological transform = parent's topological x building x twist.
Tree assemble(const PieceSet& set, const AssembleOptions& options);

struct FitOptions {
  std::uint64_t seed = 0;  // twists and tiles
  TileOptions tiles;
  Trs placement;
};

// A tree fitted to a skeleton: each internode an I (tube), each two-way fork a Y (asymmetric
// through bone scaling), each fork of three a Psi when the set has a trifurcation else a chain
// of Ys, more children a chain of Ys. The terminal joints' local transforms (similarities) aim,
// stretch and scale each piece so that its leaf rim lands on the next skeleton node with that
// segment's radius; they are the rest pose (Bone::rest == Tree::pose). Uses the skeleton root
// with the most descendants. Throws PiecesError when the set lacks a tube or a fork piece, or
// the skeleton has no segment.
Tree fit_skeleton(const PieceSet& set, const Skeleton& skeleton, const FitOptions& options);

// ---- poses, wind and skinning (section 4.3) -------------------------------------------------

// Bone world matrices from per-bone locals (parents first).
std::vector<Mat4> bone_world(const Tree& tree, std::span<const Trs> locals);

// `base` (usually tree.pose) with every terminal joint turned by a seeded random rotation of up
// to max_degrees about an axis in its rim plane; root joints stay rigid.
std::vector<Trs> random_pose(const Tree& tree, std::span<const Trs> base, std::uint64_t seed,
                             double max_degrees = 12.0);

struct WindClip {
  std::vector<double> times;  // seconds, increasing; the last key equals the first (a loop)
  // rotations[key][bone]: the local rotation of every bone at that key (translation and scale
  // stay those of the base pose)
  std::vector<std::vector<Quat>> rotations;
};
struct WindOptions {
  std::uint64_t seed = 0;
  double period = 4.0;       // seconds
  int keys = 9;              // keyframes including the closing one
  double max_degrees = 6.0;  // sway amplitude at the tips; smaller near the root
  Vec3 direction{1, 0, 0};   // horizontal wind direction
};
WindClip wind_clip(const Tree& tree, std::span<const Trs> base, const WindOptions& options);

struct SkinnedPiece {
  std::vector<Vec3> positions;  // world space, one per vertex of the LOD mesh
  std::vector<Vec3> normals;    // unit
};
// Linear blend skinning of one placed piece: v' = sum_j w_j * world[offset + j] * IBM_j * v.
SkinnedPiece skin_piece(const PieceSet& set, const Tree& tree, std::span<const Mat4> world,
                        std::uint32_t placed, std::size_t lod = 0);

// ---- level of detail (section 4.4) ----------------------------------------------------------

// Phong tessellation adapted to quads: every base quad split into segments x segments, points
// placed by bilinear interpolation of the corners then pulled towards the four tangent planes
// (Boubekeur & Alexa 2008, with bilinear weights); shape factor alpha.
PieceMesh tessellate(const PieceMesh& base, int segments, double alpha = 0.75);

// The tessellation level of an edge at run time: depends only on the midpoint of its two
// vertices (symmetric in them) and the camera, exponentially decreasing with distance.
int edge_tessellation_level(const Vec3& a, const Vec3& b, const Vec3& camera, int max_level,
                            double near_distance);

// ---- tiles (section 5.1) --------------------------------------------------------------------

// A seeded texture-array slice per base quad of one placed piece.
std::vector<std::uint16_t> assign_tiles(const PieceMesh& base, const TileOptions& options,
                                        std::uint64_t seed, std::uint32_t placed);

// ---- forests --------------------------------------------------------------------------------

struct Forest {
  std::vector<Tree> trees;  // e.g. --poses K: K copies of one topology, each in its own pose
};

// K copies of `tree` placed on a row `spacing` apart along x, copy k in random_pose(seed + k)
// (copy 0 keeps tree.pose), each with its own seeded tiles.
Forest pose_copies(const PieceSet& set, const Tree& tree, int copies, std::uint64_t seed,
                   double spacing, const TileOptions& tiles = {});

}  // namespace ramus::pieces
// contract: ready
