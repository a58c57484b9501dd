// The files the C++ back ends write, one writer each: a plan's wiring (cpp_plan_source.cc) and
// its header (cpp_plan_header.cc); a toolbox's skeleton header (cpp_skeleton_header.cc) and
// source (cpp_skeleton_source.cc). Each writes straight to the stream of its output.
#pragma once

#include "backend.h"
#include "cpp_plan_context.h"
#include "model.h"

#include <ostream>
#include <string>

namespace gfec::cpp_backend {

/// plan.cpp: the factories that create the instances and define the rules (Table I).
void emit_plan_source(const PlanContext &c, std::ostream &out);

/// plan.hpp: the factory's declaration and the toolbox headers it needs.
void emit_plan_header(const PlanContext &c, std::ostream &out);

/// <toolbox>_toolbox.h: the environment class and one class per template, bodies to fill in.
void emit_skeleton_header(const model::Model &model, const model::Toolbox &box, const EmitOptions &options,
                          std::ostream &out);

/// The source beside it: a body per member function that says what to do and, until it is
/// written, makes the component fail with "not implemented".
void emit_skeleton_source(const model::Model &model, const model::Toolbox &box, const EmitOptions &options,
                          const std::string &source_name, std::ostream &out);

}  // namespace gfec::cpp_backend
