#include "cli/guarded.hpp"

#include <cstdio>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>

#include "cli/commands.hpp"
#include "fabform/error.hpp"

namespace fabform::cli {
namespace {

int report(const char* what, int status) {
  std::fprintf(stderr, "fabform: error: %s\n", what);
  return status;
}

}  // namespace

int guarded(const std::function<int()>& command) {
  try {
    return command();
  } catch (const InputError& error) {
    return report(error.what(), kExitBadInput);
  } catch (const std::invalid_argument& error) {  // the library's own check of a value the scene gave
    return report(error.what(), kExitBadInput);
  } catch (const SystemError& error) {
    return report(error.what(), kExitSystemRefused);
  } catch (const std::system_error& error) {  // a file system call that failed
    return report(error.what(), kExitSystemRefused);
  } catch (const std::bad_alloc&) {
    return report("out of memory: the machine cannot hold this run; use fewer nodes or free memory",
                  kExitSystemRefused);
  } catch (const std::exception& error) {
    const std::string text = std::string("internal error, a bug in fabform (please report it with the scene): ") + error.what();
    return report(text.c_str(), kExitInternalError);
  } catch (...) {
    return report("internal error, a bug in fabform (please report it with the scene): an unknown exception",
                  kExitInternalError);
  }
}

}  // namespace fabform::cli
