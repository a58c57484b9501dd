#include "afp/status.h"

namespace afp {

const char* to_string(Status status) {
  switch (status) {
    case Status::NotStarted: return "not started";
    case Status::Running: return "running";
    case Status::Succeeded: return "succeeded";
    case Status::Interrupted: return "interrupted";
    case Status::Failed: return "failed";
    case Status::Stopped: return "stopped";
  }
  return "?";
}

}  // namespace afp
