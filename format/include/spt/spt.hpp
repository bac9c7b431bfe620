// Umbrella header for libspt.
#pragma once

#include "spt/limits.hpp"
#include "spt/reader.hpp"
#include "spt/render.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"
#include "spt/utf8.hpp"
#include "spt/version.hpp"
#include "spt/writer.hpp"
