// The PLCopen reader's state while it reads one project into the IEC program model. Internal to
// compiler/plcopen/; the loader calls the row's reader (plcopen_reader.h).
//
//   xml_text.{h,cc}       where each element, attribute and text is in the file;
//   plcopen_reader.cc     the project: its namespace, POUs, variables, actions and tasks;
//   sfc_body.cc           an SFC body's graph (steps, transitions, divergences, convergences,
//                         jumps, action blocks), linked by localId/refLocalId alone;
//   network_body.cc       FBD and LD networks (bodies, conditions) as the ST text they mean;
//   iec_duration.cc       TIME literals.
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "iec/iec_model.h"
#include "plcopen/xml_text.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gfec::plcopen {

class Reader {
public:
  Reader(const XmlFile &xml, ast::File &file, Diagnostics &diag) : xml_(xml), file_(file), diag_(diag) {}

  /// Reads the project below `root` (the `<project>` element).
  iec::Project read_project(const pugi::xml_node &root);

private:
  // ---------------------------------------------------------- plcopen_reader.cc
  void read_pou(const pugi::xml_node &pou, iec::Project &project);
  void read_interface(const pugi::xml_node &interface, iec::Pou &pou);
  /// A functionBlock POU with an SFC, ST, FBD or LD body (docs/iec.md "Function blocks"); another
  /// body is reported.
  void read_function_block(const pugi::xml_node &node, iec::Pou &pou, iec::Project &project);
  void read_variable(const pugi::xml_node &v, iec::Section section, bool constant, iec::Pou &pou);
  /// The named actions of POU `pou_node` (`<actions>`), their bodies in ST or SFC.
  void read_actions(const pugi::xml_node &actions, const pugi::xml_node &pou_node, iec::Pou &pou);
  /// The tasks and the globalVars of every configuration and resource below `instances`.
  void read_tasks(const pugi::xml_node &instances, iec::Project &project);
  /// A configuration's or resource's `globalVars` into project.globals.
  void read_globals(const pugi::xml_node &section, iec::Project &project);

  // ---------------------------------------------------------- sfc_body.cc
  /// Where one SFC goes: a program's or function block's body into Pou::steps/transitions, an
  /// action's body into Action::steps/transitions. The inline actions of its steps are actions of
  /// the POU either way, appended to `actions`.
  struct SfcInto {
    std::vector<iec::Step> &steps;
    std::vector<iec::Transition> &transitions;
    std::vector<iec::Action> &actions;
  };
  /// The SFC `sfc` of POU `pou_node` (whose `<transitions>` its references name).
  void read_sfc(const pugi::xml_node &sfc, const pugi::xml_node &pou_node, SfcInto into);

  // ---------------------------------------------------------- network_body.cc
  friend class Network;
  /// An FBD or LD body (`<FBD>`, `<LD>`) as the ST statements it means (docs/iec.md "FBD and LD
  /// bodies"), or nullopt after reporting what it cannot read.
  std::optional<ast::Block> read_network(const pugi::xml_node &body);
  /// The value flowing into `point` (a connectionPointIn of element `owner`) from the FBD/LD
  /// elements of `body`, as an ST expression; null after reporting.
  ast::ExprPtr network_value(const pugi::xml_node &body, const pugi::xml_node &owner, const pugi::xml_node &point);

  // ---------------------------------------------------------- shared
  /// A name the tree can view: kept in the file's strings.
  std::string_view keep(std::string text) { return file_.strings.emplace_back(std::move(text)); }
  /// The attribute's value as a name located at it (its decoded value, kept).
  ast::Name name_of(const pugi::xml_node &node, std::string_view attribute);
  /// Whether `name` is an IEC identifier (what the chart language can name too); reports it if not.
  bool identifier(const ast::Name &name, std::string_view what);
  /// An ST expression or statement list in located text.
  ast::ExprPtr expression(const LocatedText &text);
  std::optional<ast::Block> statements(const LocatedText &text);
  /// "step 'Fill' (localId 4)", for messages.
  std::string describe(const pugi::xml_node &node) const;
  SourceRange at(const pugi::xml_node &node) const { return xml_.range(node); }
  /// A located error about what gfec does not read (yet).
  void not_supported(const pugi::xml_node &node, const std::string &message);

  const XmlFile &xml_;
  ast::File &file_;
  Diagnostics &diag_;
  /// The N of STEP_inlineN, counted over all the SFCs of one POU (its body's and its actions'), so
  /// that two of its inline actions never share a name. read_pou starts it again.
  int inline_actions_ = 0;
};

}  // namespace gfec::plcopen
