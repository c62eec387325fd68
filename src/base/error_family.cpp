#include "twb/error_family.h"

#include <filesystem>
#include <system_error>

#include "twb/input_error.h"
#include "twb/solver_failure.h"

namespace twb {

IoError::IoError(const std::string& failed, const std::string& path, int error_number)
    : std::runtime_error(failed + " '" + path + "': " + std::generic_category().message(error_number)),
      path_(path),
      error_number_(error_number) {}

IoError::IoError(const std::string& what) : std::runtime_error(what) {}

ErrorReport report_error(std::exception_ptr error) {
  constexpr const char* report = " (a bug in twb: please report it with the scene and the command)";
  try {
    std::rethrow_exception(error);
  } catch (const InputError& e) {
    return {ErrorKind::input, e.what()};
  } catch (const std::invalid_argument& e) {
    return {ErrorKind::input, std::string("twb: error: ") + e.what()};
  } catch (const SolverFailure& e) {
    return {ErrorKind::solver, std::string("twb: solver failure: ") + e.what()};
  } catch (const IoError& e) {
    return {ErrorKind::io, std::string("twb: I/O error: ") + e.what()};
  } catch (const std::filesystem::filesystem_error& e) {
    // Its what() holds the operation, the system's reason and the paths.
    return {ErrorKind::io, std::string("twb: I/O error: ") + e.what()};
  } catch (const std::exception& e) {
    return {ErrorKind::internal, std::string("twb: internal error: ") + e.what() + report};
  } catch (...) {
    return {ErrorKind::internal, std::string("twb: internal error: an exception of unknown type") + report};
  }
}

}  // namespace twb
