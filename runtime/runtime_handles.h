// The C API's opaque handles, shared by the files that implement ramus_runtime.h
// (ramus_runtime.cpp: load and grow; ramus_mesher.cpp: the mesher), with the error guard of
// c_api_guard.h. Internal: nothing outside runtime/ includes it.
#pragma once

#include "compiler/ir.h"
#include "core/skeleton.h"
#include "runtime/c_api_guard.h"

struct ramus_grammar {
  ramus::ir::Grammar g;
};

struct ramus_skeleton {
  ramus::Skeleton s;
};
