// The execution environment of the test toolboxes (tests/run/cpp/*_toolbox.h): a robot whose
// sensors a script sets, one line per executor step. A line lists words (`touch`: the sensor
// reads true) and values (`lane=25`); `set:walldist=40` writes a config entry from outside the
// plan before the step, as an application would. Components log what they do to `out`.
#pragma once

#include <iostream>
#include <map>
#include <sstream>
#include <string>

class ScriptedEnv {
public:
  /// Takes this step's line; returns the `set:` writes it asks for (entry -> text).
  std::map<std::string, std::string> next(const std::string &line) {
    words_.clear();
    std::map<std::string, std::string> writes;
    std::istringstream in(line);
    for (std::string word; in >> word;) {
      auto eq = word.find('=');
      std::string name = word.substr(0, eq);
      std::string value = eq == std::string::npos ? "1" : word.substr(eq + 1);
      if (name.rfind("set:", 0) == 0) writes[name.substr(4)] = value;
      else words_[name] = value;
    }
    return writes;
  }

  /// The sensor is in this step's line.
  bool has(const std::string &name) const { return words_.count(name) > 0; }

  /// Its value (0 if absent).
  double value(const std::string &name) const {
    auto it = words_.find(name);
    return it == words_.end() ? 0 : std::stod(it->second);
  }

  std::ostream &out = std::cout;

private:
  std::map<std::string, std::string> words_;
};
