// SPDX-License-Identifier: LGPL-2.1-or-later
// `sliceform`: the command line face of the core. Errors are printed as one line on stderr
// and mapped to the exit codes documented in --help.
#include <Standard_Failure.hxx>

#include <filesystem>
#include <iostream>

#include "cli/commands.hpp"
#include "support/error.hpp"
#include "support/free_memory.hpp"

namespace {

constexpr const char* kFooter = R"(Exit codes:
  0  success
  1  the design cannot be built (too thin for these settings, not stable, interlocks or
     split patches left), or an internal error (a bug: please report it with the input)
  2  wrong command line
  3  the model cannot be used (unreadable, not a closed solid, ...)
  4  a parameter is out of range
  5  an output cannot be written
  6  cancelled)";

int exitCode(sliceform::ErrorKind kind) {
  switch (kind) {
    case sliceform::ErrorKind::BadInput:
      return 3;
    case sliceform::ErrorKind::BadParameter:
      return 4;
    case sliceform::ErrorKind::Io:
      return 5;
    case sliceform::ErrorKind::Geometry:
    case sliceform::ErrorKind::Unbuildable:
      return 1;
    case sliceform::ErrorKind::Cancelled:
      return 6;
  }
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
#if !SLICEFORM_MIMALLOC
  // With the C library's malloc (mimalloc not installed when this was built): peak memory,
  // occ/Top.brep: 261-330 MB in six runs with glibc's arenas, 230-259 MB in three with one a
  // core and the trim before the STEP file (DesignFilesWriter::start), 240 MB with two a core
  // (stop 44), which stops the STEP writer waiting on the pool's arenas.
  // support/free_memory.hpp says why. mimalloc keeps a heap a thread, and needs none of it.
  sliceform::arenasForWorkingThreads();
#endif
  CLI::App app{
      "sliceform: turn a solid (STEP, IGES, BREP, STL, OBJ, OFF) into a paper sliceform.\n"
      "Lengths are millimetres."};
  app.footer(kFooter);
  app.require_subcommand(1);
  sliceform::cli::Run slice = sliceform::cli::addSliceCommand(app);
  sliceform::cli::Run design = sliceform::cli::addDesignCommand(app);
  sliceform::cli::Run coupon = sliceform::cli::addCouponCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    if (app.got_subcommand("slice")) slice();
    if (app.got_subcommand("design")) design();
    if (app.got_subcommand("coupon")) coupon();
    return 0;
  } catch (const sliceform::Error& e) {
    std::cerr << "sliceform: " << e.what() << "\n";
    return exitCode(e.kind());
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << "sliceform: cannot write " << e.path1().string() << ": " << e.code().message() << "\n";
    return 5;
  } catch (const std::exception& e) {
    std::cerr << "sliceform: internal error: " << e.what() << "\n";
    return 1;
  } catch (const Standard_Failure& e) {
    // OCCT's exceptions do not derive from std::exception; the core guards its calls, so
    // one arriving here is a bug, but it must still end as a message, not an abort.
    std::cerr << "sliceform: internal error in OpenCASCADE: " << e.GetMessageString() << "\n";
    return 1;
  } catch (...) {
    std::cerr << "sliceform: internal error of an unknown kind\n";
    return 1;
  }
}
