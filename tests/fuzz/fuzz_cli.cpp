// libFuzzer target: the command-line parser. The input is split at NUL bytes into arguments. Any
// argument list either parses or is an InputError; with no input file, the overrides are applied to
// the built-in scene too (no file is read).
#include "options/options.hpp"
#include "core/base/error.hpp"

#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args(1);
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == 0) args.emplace_back();
        else args.back() += char(data[i]);
    }
    try {
        const shadelab::Options options = shadelab::parseOptions(args);
        if (options.input.empty()) shadelab::sceneFromOptions(options);
    } catch (const shadelab::InputError&) {
    }
    return 0;
}
