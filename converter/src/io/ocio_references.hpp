// A guard in front of OpenColorIO: OCIO 2.1 follows a colour space's references to other colour
// spaces, looks and named transforms by recursion without noticing a loop, so a config whose
// colour space refers (directly or through others) to itself overflows the stack inside OCIO
// (SIGSEGV) when a processor is asked for. The config's YAML is read here first and every
// reference followed; a loop is an error that names it.
#pragma once

#include <string>

#include "spt/result.hpp"

namespace spt::io {

// Refuses a config file whose colour spaces, named transforms, looks, views or view transforms
// refer to each other in a loop ("colour space 'a' -> look 'l' -> colour space 'a'"), or that is
// not YAML. Says nothing about anything else in it (OCIO checks the rest).
Status check_ocio_references(const std::string& path);

}  // namespace spt::io
