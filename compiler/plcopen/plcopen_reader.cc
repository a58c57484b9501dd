// The PLCopen reader's entry point and the project around the SFC bodies: the namespace, the
// POUs and their variables, named actions, and the tasks that give a program its period.
#include "plcopen/plcopen_reader.h"
#include "iec/iec_text.h"

#include "escape.h"
#include "iec/lower.h"
#include "iec/st_fragment.h"
#include "input_languages.h"
#include "plcopen/iec_duration.h"
#include "plcopen/reader_context.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <memory>

namespace gfec::plcopen {

namespace {

/// The namespaces of the three TC6 schemas in use: 1.0 (tc6.xsd), 2.0 and 2.01.
constexpr std::string_view kNamespaces[] = {"http://www.plcopen.org/xml/tc6.xsd", "http://www.plcopen.org/xml/tc6_0200",
                                            "http://www.plcopen.org/xml/tc6_0201"};

bool is_true(std::string_view v) { return v == "true" || v == "1"; }

using iec::upper;

}  // namespace

// ---------------------------------------------------------------- shared helpers

ast::Name Reader::name_of(const pugi::xml_node &node, std::string_view attribute) {
  LocatedText t = xml_.attribute_text(node, attribute);
  SourceRange r = xml_.attribute_range(node, attribute);
  return {keep(std::move(t.text)), r};
}

bool Reader::identifier(const ast::Name &name, std::string_view what) {
  bool ok = !name.text.empty() && !std::isdigit(static_cast<unsigned char>(name.text[0]));
  for (char c : name.text) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
  if (!ok)
    diag_.error(name.range, ErrorKind::Plcopen,
                name.text.empty()
                    ? fmt::format("{} without a name", what)
                    : fmt::format("{} '{}': an IEC name is letters, digits and '_', not beginning with a digit", what,
                                  text::printable(name.text)));
  return ok;
}

ast::ExprPtr Reader::expression(const LocatedText &text) {
  iec::FragmentPlace place{file_.id, text.breaks};
  if (text.blank()) {
    diag_.error(place.range(0, 0), ErrorKind::Plcopen,
                "an empty ST expression where gfec needs a condition or a value");
    return nullptr;
  }
  std::string_view kept = keep(text.text);
  return iec::parse_st_expression(kept, place, file_.strings, diag_);
}

std::optional<ast::Block> Reader::statements(const LocatedText &text) {
  iec::FragmentPlace place{file_.id, text.breaks};
  std::string_view kept = keep(text.text);
  return iec::parse_st_statements(kept, place, file_.strings, diag_);
}

std::string Reader::describe(const pugi::xml_node &node) const {
  std::string out = std::string(local_name(node));
  if (auto n = node.attribute("name"); n && *n.value()) out += fmt::format(" '{}'", n.value());
  if (auto id = node.attribute("localId")) out += fmt::format(" (localId {})", id.value());
  return text::printable(out);
}

void Reader::not_supported(const pugi::xml_node &node, const std::string &message) {
  diag_.error(at(node), ErrorKind::NotSupported, message);
}

// ---------------------------------------------------------------- the project

iec::Project Reader::read_project(const pugi::xml_node &root) {
  iec::Project project;
  for (pugi::xml_node types : root.children()) {
    if (local_name(types) != "types") continue;
    for (pugi::xml_node pous : types.children())
      if (local_name(pous) == "pous")
        for (pugi::xml_node pou : pous.children())
          if (local_name(pou) == "pou") read_pou(pou, project);
    // A data type whose base type is an elementary one or another name is an alias (docs/iec.md
    // "Type aliases"); the others (structures, enumerations, arrays, subranges) are reported
    // where a variable has one, as an unknown type is.
    for (pugi::xml_node data : types.children())
      if (local_name(data) == "dataTypes")
        for (pugi::xml_node d : data.children()) {
          if (local_name(d) != "dataType") continue;
          pugi::xml_node base;
          for (pugi::xml_node c : child(d, "baseType").children())
            if (c.type() == pugi::node_element) {
              base = c;
              break;
            }
          if (!base || child(d, "initialValue")) continue;
          ast::Name name = name_of(d, "name");
          if (local_name(base) == "derived") project.aliases.push_back({name, name_of(base, "name"), at(d)});
          else if (!base.first_child())  // <INT/>: an elementary type; <struct>, <array> ... have children
            project.aliases.push_back({name, {keep(upper(local_name(base))), at(base)}, at(d)});
        }
  }
  if (pugi::xml_node instances = child(root, "instances")) read_tasks(instances, project);
  return project;
}

void Reader::read_pou(const pugi::xml_node &node, iec::Project &project) {
  iec::Pou pou;
  inline_actions_ = 0;
  pou.name = name_of(node, "name");
  pou.range = at(node);
  if (!identifier(pou.name, "POU")) return;
  std::string_view type = node.attribute("pouType").value();
  if (type == "functionBlock") {
    pou.kind = iec::PouKind::FunctionBlock;
  } else if (type == "function") {
    pou.kind = iec::PouKind::Function;
  } else if (type != "program") {
    diag_.error(xml_.attribute_range(node, "pouType"), ErrorKind::Plcopen,
                fmt::format("POU '{}' has pouType '{}': the schema's are program, functionBlock and function",
                            pou.name.text, text::printable(type)));
    return;
  }
  if (pou.kind == iec::PouKind::FunctionBlock) {
    read_function_block(node, pou, project);
    return;
  }
  if (pou.kind != iec::PouKind::Program) {  // the lowering reports it; its insides are not read
    project.pous.push_back(std::move(pou));
    return;
  }
  if (pugi::xml_node interface = child(node, "interface")) read_interface(interface, pou);
  if (pugi::xml_node actions = child(node, "actions")) read_actions(actions, node, pou);
  // A program has one body (TC6 2.01 allows several, one per worksheet: gfec reads one).
  pugi::xml_node sfc, other;
  int bodies = 0;
  for (pugi::xml_node body : node.children()) {
    if (local_name(body) != "body") continue;
    ++bodies;
    for (pugi::xml_node b : body.children()) {
      if (b.type() != pugi::node_element || local_name(b) == "documentation" || local_name(b) == "addData") continue;
      if (local_name(b) == "SFC" && !sfc) sfc = b;
      else if (!other) other = b;
    }
  }
  if (!sfc && !other) {
    diag_.error(pou.name.range, ErrorKind::Plcopen, fmt::format("program '{}' has no body", pou.name.text));
    return;
  }
  if (!sfc && bodies == 1) {
    // A body of statements: ST as written, FBD and LD as the ST they mean (network_body.cc).
    std::string_view lang = local_name(other);
    if (lang == "ST") {
      pou.body = statements(xml_.text_below(other));
    } else if (lang == "FBD" || lang == "LD") {
      pou.body = read_network(other);
    } else {
      not_supported(other, fmt::format("program '{}': a body in {} is not supported yet; gfec reads SFC, ST, "
                                       "FBD and LD bodies",
                                       pou.name.text, text::printable(lang)));
      return;
    }
    if (!pou.body) return;  // reported
    project.pous.push_back(std::move(pou));
    return;
  }
  if (!sfc || bodies > 1) {
    pugi::xml_node what = other ? other : sfc;
    diag_.error(at(what), ErrorKind::NotSupported,
                fmt::format("program '{}': a body in {} is not supported yet; gfec reads programs whose body is "
                            "one sequential function chart (SFC)",
                            pou.name.text, text::printable(local_name(what))));
    return;
  }
  read_sfc(sfc, node, {pou.steps, pou.transitions, pou.actions});
  project.pous.push_back(std::move(pou));
}

void Reader::read_function_block(const pugi::xml_node &node, iec::Pou &pou, iec::Project &project) {
  if (pugi::xml_node interface = child(node, "interface")) read_interface(interface, pou);
  // Its actions are read whatever its body: those no step of an SFC body holds are the
  // lowering's to report, never dropped.
  if (pugi::xml_node actions = child(node, "actions")) read_actions(actions, node, pou);
  pugi::xml_node body = child(node, "body");
  if (pugi::xml_node sfc = child(body, "SFC")) {
    // An SFC function block is read as an SFC program is: each call of an instance is one scan
    // of the chart (docs/iec.md "SFC inside actions and function blocks").
    const std::size_t errors = diag_.error_count();
    read_sfc(sfc, node, {pou.steps, pou.transitions, pou.actions});
    if (pou.steps.empty() && errors == diag_.error_count())  // else a block that does nothing
      diag_.error(at(sfc), ErrorKind::Plcopen,
                  fmt::format("the SFC body of function block '{}' has no step", pou.name.text));
    project.pous.push_back(std::move(pou));
    return;
  }
  pugi::xml_node st = child(body, "ST");
  // FBD and LD are read as the ST they mean (network_body.cc), as a program's are.
  pugi::xml_node network = child(body, "FBD") ? child(body, "FBD") : child(body, "LD");
  if (!st && network) {
    pou.body = read_network(network);
    if (pou.body) project.pous.push_back(std::move(pou));
    return;
  }
  if (!st) {
    pugi::xml_node what = body ? body : node;
    for (pugi::xml_node c : body.children())
      if (c.type() == pugi::node_element && local_name(c) != "documentation" && local_name(c) != "addData") {
        what = c;
        break;
      }
    not_supported(what, fmt::format("function block '{}': a body in {} is not supported yet; gfec reads SFC, ST, FBD "
                                    "and LD bodies of function blocks",
                                    pou.name.text, body ? text::printable(local_name(what)) : "none"));
    return;
  }
  auto block = statements(xml_.text_below(st));
  if (!block) return;
  pou.body = std::move(block);
  project.pous.push_back(std::move(pou));
}

void Reader::read_interface(const pugi::xml_node &interface, iec::Pou &pou) {
  for (pugi::xml_node section : interface.children()) {
    if (section.type() != pugi::node_element) continue;
    std::string_view kind = local_name(section);
    if (kind == "documentation" || kind == "addData") continue;
    std::optional<iec::Section> s;
    if (kind == "inputVars") s = iec::Section::Input;
    else if (kind == "outputVars") s = iec::Section::Output;
    else if (kind == "localVars") s = iec::Section::Local;
    else if (kind == "externalVars") s = iec::Section::External;
    else if (kind == "inOutVars") s = iec::Section::InOut;
    if (!s) {
      if (child(section, "variable"))
        not_supported(section, fmt::format("a {} section is not supported yet: gfec reads inputVars, outputVars, "
                                           "inOutVars, localVars and externalVars",
                                           text::printable(kind)));
      continue;
    }
    bool constant = is_true(section.attribute("constant").value());
    for (pugi::xml_node v : section.children())
      if (local_name(v) == "variable") read_variable(v, *s, constant, pou);
  }
}

void Reader::read_variable(const pugi::xml_node &v, iec::Section section, bool constant, iec::Pou &pou) {
  iec::Variable var;
  var.section = section;
  var.constant = constant;
  var.name = name_of(v, "name");
  var.range = at(v);
  if (!identifier(var.name, "variable")) return;
  if (v.attribute("address")) {
    var.located = xml_.attribute_range(v, "address");
    var.address = keep(v.attribute("address").value());
  }
  pugi::xml_node type = child(v, "type");
  pugi::xml_node t;
  for (pugi::xml_node c : type.children())
    if (c.type() == pugi::node_element) {
      t = c;
      break;
    }
  if (!t) {
    diag_.error(at(v), ErrorKind::Plcopen, fmt::format("variable '{}' has no type", var.name.text));
    return;
  }
  if (local_name(t) == "derived") {
    var.type = name_of(t, "name");
  } else {
    // Elementary types are elements named as the type (<BOOL/>); string is <string/>.
    var.type = {keep(upper(local_name(t))), at(t)};
  }
  if (pugi::xml_node init = child(v, "initialValue")) {
    pugi::xml_node simple = child(init, "simpleValue");
    if (simple) var.init = expression(xml_.attribute_text(simple, "value"));
    else
      not_supported(init, fmt::format("the initial value of variable '{}' is not a simple value: arrays and "
                                      "structures are not supported yet",
                                      var.name.text));
  }
  pou.variables.push_back(std::move(var));
}

void Reader::read_actions(const pugi::xml_node &actions, const pugi::xml_node &pou_node, iec::Pou &pou) {
  // The inline actions of the steps of SFC bodies: the POU's, after its named actions (as those of
  // its body's SFC are), in the file's order.
  std::vector<iec::Action> held;
  for (pugi::xml_node a : actions.children()) {
    if (local_name(a) != "action") continue;
    iec::Action action;
    action.name = name_of(a, "name");
    action.range = at(a);
    if (!identifier(action.name, "action")) continue;
    pugi::xml_node body = child(a, "body");
    if (pugi::xml_node sfc = child(body, "SFC")) {
      // An SFC inside an action (docs/iec.md "SFC inside actions and function blocks"), read as a
      // program's SFC is.
      const std::size_t errors = diag_.error_count();
      read_sfc(sfc, pou_node, {action.steps, action.transitions, held});
      if (action.steps.empty()) {
        // Else it would pass for an action with an empty ST body.
        if (errors == diag_.error_count())
          diag_.error(at(sfc), ErrorKind::Plcopen,
                      fmt::format("the SFC body of action '{}' has no step", action.name.text));
        continue;
      }
      pou.actions.push_back(std::move(action));
      continue;
    }
    pugi::xml_node st = child(body, "ST");
    // FBD and LD are read as the ST they mean (network_body.cc), as a POU's body is.
    pugi::xml_node network = child(body, "FBD") ? child(body, "FBD") : child(body, "LD");
    if (!st && network) {
      auto block = read_network(network);
      if (!block) continue;
      action.body = std::move(*block);
      pou.actions.push_back(std::move(action));
      continue;
    }
    if (!st) {
      pugi::xml_node what = body;
      for (pugi::xml_node c : body.children())
        if (c.type() == pugi::node_element && local_name(c) != "documentation" && local_name(c) != "addData") {
          what = c;
          break;
        }
      if (!what) what = a;
      not_supported(what, fmt::format("the body of action '{}' is {}: gfec reads action bodies in ST, SFC, FBD and "
                                      "LD; {} is not supported yet",
                                      action.name.text, describe(what), local_name(what)));
      continue;
    }
    auto block = statements(xml_.text_below(st));
    if (!block) continue;
    action.body = std::move(*block);
    pou.actions.push_back(std::move(action));
  }
  for (iec::Action &h : held) pou.actions.push_back(std::move(h));
}

void Reader::read_tasks(const pugi::xml_node &instances, iec::Project &project) {
  for (pugi::xml_node configurations : instances.children()) {
    if (local_name(configurations) != "configurations") continue;
    for (pugi::xml_node configuration : configurations.children()) {
      if (local_name(configuration) != "configuration") continue;
      for (pugi::xml_node resource : configuration.children()) {
        if (local_name(resource) == "globalVars") read_globals(resource, project);
        if (local_name(resource) != "resource") continue;
        for (pugi::xml_node t : resource.children()) {
          if (local_name(t) == "globalVars") read_globals(t, project);
          if (local_name(t) != "task") continue;
          iec::Task task;
          task.name = name_of(t, "name");
          task.range = at(t);
          if (t.attribute("interval")) {
            task.interval_range = xml_.attribute_range(t, "interval");
            task.interval_ms = duration_ms(t.attribute("interval").value());
            if (!task.interval_ms || *task.interval_ms <= 0) {
              diag_.error(task.interval_range, ErrorKind::Plcopen,
                          fmt::format("task '{}' has the interval '{}': gfec reads a positive TIME literal "
                                      "(T#10ms), an XML duration (PT0.01S) or a clock time (00:00:00.010)",
                                      task.name.text, text::printable(t.attribute("interval").value())));
              task.interval_ms.reset();
            }
          }
          for (pugi::xml_node inst : t.children())
            if (local_name(inst) == "pouInstance") task.programs.push_back(name_of(inst, "typeName"));
          project.tasks.push_back(std::move(task));
        }
      }
    }
  }
}

void Reader::read_globals(const pugi::xml_node &section, iec::Project &project) {
  // Read as a POU's variables are, then moved to the file's scope (docs/iec.md "Global
  // variables"); `retain` and `persistent` mean nothing to gfec.
  iec::Pou scratch;
  bool constant = is_true(section.attribute("constant").value());
  for (pugi::xml_node v : section.children())
    if (local_name(v) == "variable") read_variable(v, iec::Section::Global, constant, scratch);
  for (iec::Variable &v : scratch.variables) project.globals.push_back(std::move(v));
}

// ---------------------------------------------------------------- the entry point

namespace {

// A UTF-16 byte-order mark (some Windows tools save PLCopen files so).
bool starts_utf16(std::string_view text) {
  return text.size() >= 2 && ((text[0] == '\xFF' && text[1] == '\xFE') || (text[0] == '\xFE' && text[1] == '\xFF'));
}

}  // namespace

bool is_xml_document(std::string_view text) {
  // Claimed, so that the reader says it is in the wrong encoding.
  if (starts_utf16(text)) return true;
  std::size_t i = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n')) ++i;
  return i < text.size() && text[i] == '<';
}

void read_plcopen_program(const std::string &main_path, std::string text, const LoadOptions &options,
                          const FileSystem &, SourceManager &sources, Diagnostics &diag, LoadResult &result) {
  result.paths.push_back(main_path);
  result.program.files.push_back(std::make_unique<ast::File>());
  ast::File &file = *result.program.files.back();
  file.id = sources.add(main_path, std::move(text), language());
  const std::string &t = sources.file(file.id).text();
  if (starts_utf16(t)) {
    diag.error({file.id, 0, 2}, ErrorKind::Xml,
               "the file is UTF-16: gfec reads PLCopen files in UTF-8; save it as UTF-8");
    return;
  }
  pugi::xml_document doc;
  pugi::xml_parse_result parsed = doc.load_buffer(t.data(), t.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!parsed) {
    auto offset =
        static_cast<std::uint32_t>(std::min<std::ptrdiff_t>(std::max<std::ptrdiff_t>(parsed.offset, 0), t.size()));
    diag.error({file.id, offset, offset}, ErrorKind::Xml, fmt::format("malformed XML: {}", parsed.description()));
    return;
  }
  XmlFile xml(file.id, t);
  pugi::xml_node root = doc.document_element();
  if (local_name(root) != "project") {
    diag.error(xml.range(root), ErrorKind::Plcopen,
               fmt::format("the root element is <{}>: a PLCopen file's is <project>", text::printable(root.name())));
    return;
  }
  std::string_view root_name = root.name();
  auto colon = root_name.find(':');
  std::string xmlns = colon == std::string_view::npos ? "xmlns" : "xmlns:" + std::string(root_name.substr(0, colon));
  std::string_view ns = root.attribute(xmlns.c_str()).value();
  bool known = false;
  for (std::string_view k : kNamespaces) known = known || ns == k;
  if (!known) {
    diag.error(xml.attribute_range(root, xmlns), ErrorKind::Plcopen,
               ns.empty()
                   ? std::string("the <project> has no namespace: gfec reads PLCopen TC6 XML, whose namespace is "
                                 "http://www.plcopen.org/xml/tc6_0201 (or tc6_0200, or tc6.xsd)")
                   : fmt::format("the namespace '{}' is not one gfec reads: it reads PLCopen TC6 XML in "
                                 "http://www.plcopen.org/xml/tc6_0201, tc6_0200 and tc6.xsd",
                                 text::printable(ns)));
    return;
  }
  Reader reader(xml, file, diag);
  iec::Project project = reader.read_project(root);
  // The program the tasks run is the one compiled when --chart names none (docs/iec.md).
  std::vector<std::string> run;
  for (const iec::Task &task : project.tasks)
    for (const ast::Name &p : task.programs)
      for (const iec::Pou &pou : project.pous)
        if (pou.kind == iec::PouKind::Program && upper(pou.name.text) == upper(p.text) &&
            std::find(run.begin(), run.end(), std::string(pou.name.text)) == run.end())
          run.emplace_back(pou.name.text);
  if (run.size() == 1) result.default_chart = run.front();
  iec::lower(std::move(project), file, diag, options.period_ms);
}

}  // namespace gfec::plcopen
