// The .rmb binary grammar format (docs/binary-format.md): the entry header of formats/rmb/ for
// the stages above it. Encoding and decoding with verification (rmb_codec.h), decompiling back
// to .ramus text (rmb_decompile.h), the `pieces` and `voxels` blocks as the file stores them
// (rmb_pieces_ast.h, rmb_voxels.h) and the portable locations it records (rmb_paths.h). The
// embeddable runtime includes only rmb_codec.h, the part that needs no grammar front end.
#pragma once

#include "formats/rmb/rmb_codec.h"
#include "formats/rmb/rmb_decompile.h"
#include "formats/rmb/rmb_paths.h"
#include "formats/rmb/rmb_pieces_ast.h"
#include "formats/rmb/rmb_voxels.h"
