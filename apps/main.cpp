// phongrast: render scene files and meshes from the command line.
// Exit status: 0 on success, 2 for bad input or a bad command line (the
// message names the file, line or field and what was expected), 130 after
// Ctrl-C (nothing written), 1 for anything unexpected.
#include <exception>
#include <functional>
#include <iostream>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "interrupt.hpp"
#include "process_heap.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/version.hpp"

int main(int argc, char** argv) {
    using namespace phongrast::cli;
    CLI::App app("phongrast " PHONGRAST_VERSION_STRING
                 ": a software renderer with Phong lighting and painter's order. "
                 "Scene files follow docs/scene-format.md.",
                 "phongrast");
    app.set_version_flag("--version", "phongrast " PHONGRAST_VERSION_STRING);
    app.require_subcommand(1);
    RenderCommand render;
    SheetCommand sheet;
    GenerateCommand generate;
    BatchCommand batch;
    ThumbnailCommand thumbnail;
    // Setting up a command's flags in CLI11 (hundreds of option objects and
    // strings) took about 2.4 ms for all five, a fifth of `phongrast
    // --version`; a process runs one command, named by its first argument,
    // so only that one is set up. With no command named (--help, --version,
    // a mistake) all are, so that the top-level help and errors list them.
    const std::string named = argc > 1 ? argv[1] : "";
    const std::pair<const char*, std::function<void()>> commands[] = {
        {"render", [&] { add_render_command(app, render); }},
        {"sheet", [&] { add_sheet_command(app, sheet); }},
        {"generate", [&] { add_generate_command(app, generate); }},
        {"batch", [&] { add_batch_command(app, batch); }},
        {"thumbnail", [&] { add_thumbnail_command(app, thumbnail); }},
    };
    bool any = true;
    for (const auto& [name, add] : commands) any = any && named != name;
    if (any && !named.empty() && named[0] != '-') {
        std::cerr << "phongrast: error: unknown command '" << named
                  << "'; expected render, sheet, generate, batch or thumbnail; see phongrast --help\n";
        return 2;
    }
    if (argc == 2 && named == "--version") {
        std::cout << "phongrast " PHONGRAST_VERSION_STRING "\n";  // as CLI11's version flag prints it
        return 0;
    }
    // A process that renders once pays for every fresh page it writes; batch
    // (long-running, its own memory rules) keeps malloc's defaults.
    if (named == "render" || named == "thumbnail" || named == "sheet" || named == "generate") prepare_one_off_heap();
    for (const auto& [name, add] : commands) {
        if (any || named == name) add();
    }

    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& success) {
        return app.exit(success);  // --help, --version
    } catch (const CLI::ParseError& error) {
        // One line, like every other error (CLI11's own printout takes three).
        std::string command = "phongrast";
        for (const CLI::App* sub : app.get_subcommands()) command += " " + sub->get_name();
        std::cerr << "phongrast: error: " << error.what() << "; see " << command << " --help\n";
        return 2;
    }

    // The command given (CLI11's got_subcommand(name) throws for a command
    // that was not set up, which all but the named one are).
    const std::string given = app.get_subcommands().empty() ? "" : app.get_subcommands().front()->get_name();
    const auto got = [&given](const char* name) { return given == name; };
    // render and sheet stop cleanly on Ctrl-C; batch keeps the default (its
    // supervisor and workers end, and a re-run resumes from the log).
    if (got("render") || got("sheet")) catch_interrupts();
    try {
        if (got("render")) return run_render(render);
        if (got("sheet")) return run_sheet(sheet);
        if (got("generate")) return run_generate(generate);
        if (got("batch")) return run_batch(batch);
        if (got("thumbnail")) return run_thumbnail(thumbnail);
    } catch (const phongrast::RenderCancelled&) {
        // Only Ctrl-C cancels here; every file is written by rename, so none is half-written.
        std::cerr << "\nphongrast: interrupted; no output written\n";
        return kInterruptedExitStatus;
    } catch (const phongrast::io::FileError& error) {
        std::cerr << "phongrast: error: " << error.what() << '\n';
        return 2;
    } catch (const std::logic_error& error) {
        // invalid_argument, out_of_range, length_error: the library refusing
        // what it was given (a value, an index, a size), never a crash.
        std::cerr << "phongrast: error: " << error.what() << '\n';
        return 2;
    } catch (const std::exception& error) {
        std::cerr << "phongrast: internal error: " << error.what() << '\n';
        return 1;
    }
    return 2;
}
