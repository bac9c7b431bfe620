// The one table of the options a paint job takes. Every front end reads it: the CLI11 options of
// `spt paint` and `spt plan` and their --help (cli/paint_options.cpp), the job a plan stores
// (plan_job.hpp), the painter.options metadata (PaintJob::canonical), and the list the Blender
// add-on shows (`spt paint --options-json`). Adding an option is one row in option_table.cpp.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "job/paint_job.hpp"

namespace spt::job {

enum class OptionKind {
    Flag,     // present or not
    Integer,  // a whole number in lo..hi
    Number,   // a finite number in lo..hi
    Choice,   // one of `choices`
    Text,     // free text, checked by the row's setter
    Path,     // a file or folder the job reads (a plan stores it absolute)
    List,     // repeatable text, checked by the row's setter
};

// What an option is about, which decides where it may appear.
enum class OptionScope {
    Painting,  // shapes the painting: a plan stores it with the job its tasks paint
    Shot,      // set per shot by a plan (seed, frames, rate): given to spt plan, not stored as such
    Run,       // how this one run works (threads, progress, extra outputs): never in a plan
    Planning,  // how spt plan splits a clip: spt plan only
};

inline constexpr unsigned kForPaint = 1, kForPlan = 2;  // OptionRow::commands

struct OptionRow {
    std::string name;      // --name
    std::string metavar;   // the value's name in --help ("N", "DB"); empty for a flag
    OptionKind kind = OptionKind::Text;
    std::string def;       // the default as --help and --options-json show it; empty: none
    double lo = 0, hi = 0;          // Integer and Number: the accepted range
    std::string unit;               // Integer and Number: said in range errors ("pixels")
    std::vector<std::string> choices;  // Choice
    std::string help;
    unsigned styles = kAllStyles;   // the styles the option shapes (style_bit)
    OptionScope scope = OptionScope::Painting;
    unsigned commands = kForPaint | kForPlan;
    std::string group;     // --help group; empty: the first
    bool addon = false;    // shown in the Blender add-on's panel

    // Stores a value into the job; the range (Integer, Number) and the choices are checked
    // before. Returns "" or what was expected ("expected R,G,B (0..255)"): the caller names the
    // option and the value given.
    std::function<std::string(PaintJob&, const std::string&)> set;
    // The job's value as a plan stores it (Painting rows): a flag "true", a list one text per
    // value; empty when absent.
    std::function<std::vector<std::string>(const PaintJob&)> get;
    // A check of the stored value against the rest of the job, after every option is stored
    // (a value the job's style cannot honour): "" or the whole message.
    std::function<std::string(const PaintJob&)> check;
    // painter.options: the rows with a rank, in rank order, each writing " key=value" or nothing.
    int canon_rank = 0;
    std::function<void(std::ostream&, const PaintJob&)> canon;
};

// The table, in --help order. Mutable so that a test build can add a row and find it in every
// front end; nothing else changes it.
std::vector<OptionRow>& option_rows();
const OptionRow* find_option(const std::string& name);

// One value given for `row` (a flag: "true"): checks the range or the choices, then stores it.
// Returns "" or the whole message ("--sets: expected 3..10, got '12'").
std::string apply_option(const OptionRow& row, const std::string& value, PaintJob& job);

// After every given option is stored: the checks between options and the defaults that follow
// others (lambda and colour step from the target, ROI files read, colour spaces resolved, the
// options a style does not take). `given` names the options given. Returns "" or the message.
std::string finish_job(PaintJob& job, const std::vector<std::string>& given);

// The table as JSON, for the Blender add-on and other front ends (spt paint --options-json).
std::string options_json();

}  // namespace spt::job
