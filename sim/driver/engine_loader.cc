#include "driver/engine_loader.h"

#include <dlfcn.h>

#include "driver/engine_abi.h"

namespace carbot::driver {
namespace {

void* symbol(void* handle, const char* name, const std::string& library) {
  void* p = dlsym(handle, name);
  if (!p) throw LoadError(library + ": no entry point " + name);
  return p;
}

}  // namespace

LoadedEngine::LoadedEngine(const std::string& library) {
  handle_ = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle_) {
    const char* why = dlerror();
    throw LoadError(
        std::string("cannot load the engine: ") + (why ? why : library) +
        "\n  (carbot-sim's robot libraries implement samples/linebot.iface, cleanbot.iface and fetchbot.iface)");
  }
  auto size = reinterpret_cast<size_t (*)()>(symbol(handle_, kEngineSize, library));
  init_ = reinterpret_cast<void (*)(void*)>(symbol(handle_, kEngineInit, library));
  run_ = reinterpret_cast<void (*)(void*)>(symbol(handle_, kEngineRun, library));
  status_ = reinterpret_cast<int (*)(const void*)>(symbol(handle_, kEngineStatus, library));
  fini_ = reinterpret_cast<void (*)(void*)>(dlsym(handle_, kEngineFini));
  state_ = reinterpret_cast<int (*)(const void*)>(dlsym(handle_, kEngineState));
  places_ = reinterpret_cast<int (*)()>(dlsym(handle_, kEnginePlaces));
  activation_ = reinterpret_cast<unsigned (*)(const void*, int)>(dlsym(handle_, kEngineActivation));
  set_agent_ = reinterpret_cast<void (*)(void*, int)>(dlsym(handle_, kEngineSetAgent));
  set_context_ = reinterpret_cast<void (*)(void*, CarbotRobot*)>(symbol(handle_, kEngineSetContext, library));
  report_ = reinterpret_cast<void (*)(void*, int, int)>(dlsym(handle_, kEngineReport));
  instance_activation_ =
      reinterpret_cast<unsigned (*)(const void*, int, int)>(dlsym(handle_, kEngineInstanceActivation));
  // max_align_t alignment: vector storage comes from operator new, which guarantees it.
  memory_.assign(size() + 1, 0);
}

LoadedEngine::~LoadedEngine() {
  finish();
  if (handle_) dlclose(handle_);
}

}  // namespace carbot::driver
