// Choice options on the command line: an enum read by the names its `enum_names` lists
// (the one table a worker's job uses too: distrib/wire/job_fields.h).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "distrib/wire/job_fields.h"

namespace povwall::cli {

template <distrib::NamedEnum E>
std::string choice_name(E e) {
    return distrib::job_fields_detail::name_of(e);
}

// An option taking one of E's names (and nothing else); its default is the value `out`
// holds.
template <distrib::NamedEnum E>
CLI::Option* add_choice_option(CLI::App& app, const std::string& flag, E& out,
                               const std::string& help) {
    std::vector<std::string> names;
    for (const auto& [value, name] : enum_names(out)) names.emplace_back(name);
    return app
        .add_option_function<std::string>(
            flag,
            [&out](const std::string& name) {
                out = *distrib::job_fields_detail::named<E>(name);
            },
            help)
        ->check(CLI::IsMember(names))
        ->default_str(choice_name(out));
}

}  // namespace povwall::cli
