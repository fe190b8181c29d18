// A job is a struct that lists its fields once:
//
//     template <class Self, class Visit> static void fields(Self& self, Visit&& v) {
//         v("width", self.width);
//         ...
//     }
//
// and the templates here write it to JSON (by name) and to a command line (--name=value,
// one argument per entry of a list or map) and read both back. A field added to fields()
// travels both ways with no other change. A field whose type is itself a job (a base
// struct, or a member with fields()) is flattened: its fields sit beside the others.
//
// JSON errors are nlohmann::json exceptions (a missing field, a wrong type, a bad enum
// name); command-line errors are JobArgumentError, naming the argument.
#pragma once

#include <array>
#include <charconv>
#include <concepts>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace povwall::distrib {

struct JobArgumentError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// `To`, const when `From` is: a job's fields() names a base part of `Self` with it.
template <class From, class To>
using copy_const_t = std::conditional_t<std::is_const_v<From>, const To, To>;

// A struct that lists its fields (see above).
template <class T>
concept JobFields = requires(T& t) {
    T::fields(t, [](const char*, auto&) {});
};

// An enum travels by name: a free `enum_names(E)` found by lookup returns its
// {value, name} pairs.
template <class E>
concept NamedEnum = std::is_enum_v<E> && requires(E e) {
    enum_names(e);
};

namespace job_fields_detail {

[[noreturn]] inline void bad_json_value(std::string_view field, const nlohmann::json& v) {
    throw nlohmann::json::other_error::create(
        501, "bad " + std::string(field) + ": " + v.dump(), nullptr);
}

[[noreturn]] inline void malformed(std::string_view name, std::string_view value) {
    throw JobArgumentError("malformed --" + std::string(name) + "=" + std::string(value));
}

template <NamedEnum E>
std::string name_of(E e) {
    for (const auto& [value, name] : enum_names(e))
        if (value == e) return name;
    return "";
}

template <NamedEnum E>
std::optional<E> named(std::string_view s) {
    for (const auto& [value, name] : enum_names(E{}))
        if (name == s) return value;
    return std::nullopt;
}

// --- JSON -------------------------------------------------------------------------

template <class T>
nlohmann::json json_of(const T& v) {
    if constexpr (NamedEnum<T>) {
        return name_of(v);
    } else if constexpr (std::same_as<T, char>) {
        return std::string(1, v);
    } else {
        return v;
    }
}
template <class T>
nlohmann::json json_of(const std::optional<T>& v) {
    return v ? json_of(*v) : nlohmann::json();
}

template <class T>
void read_json(std::string_view name, const nlohmann::json& j, T& out) {
    if constexpr (NamedEnum<T>) {
        const auto e = named<T>(j.get<std::string>());
        if (!e) bad_json_value(name, j);
        out = *e;
    } else if constexpr (std::same_as<T, char>) {
        const std::string s = j.get<std::string>();
        if (s.size() != 1) bad_json_value(name, j);
        out = s[0];
    } else if constexpr (std::integral<T> && !std::same_as<T, bool>) {
        // Whole numbers only, in T's range (a writer never writes 1.5 or 1e300 here, and
        // casting those would be undefined).
        if (j.is_number_unsigned()) {
            const uint64_t v = j.get<uint64_t>();
            if (!std::in_range<T>(v)) bad_json_value(name, j);
            out = T(v);
        } else if (j.is_number_integer()) {
            const int64_t v = j.get<int64_t>();
            if (!std::in_range<T>(v)) bad_json_value(name, j);
            out = T(v);
        } else {
            bad_json_value(name, j);
        }
    } else {
        out = j.get<T>();
    }
}
// Lists element by element, so that each element is read as the scalars above.
template <class T>
void read_json(std::string_view name, const nlohmann::json& j, std::vector<T>& out) {
    if (!j.is_array()) bad_json_value(name, j);
    out.clear();
    out.reserve(j.size());
    for (const nlohmann::json& e : j) read_json(name, e, out.emplace_back());
}
template <class T, size_t N>
void read_json(std::string_view name, const nlohmann::json& j, std::array<T, N>& out) {
    if (!j.is_array() || j.size() != N) bad_json_value(name, j);
    for (size_t k = 0; k < N; ++k) read_json(name, j[k], out[k]);
}
template <class T>
void read_json(std::string_view name, const nlohmann::json& j, std::optional<T>& out) {
    if (j.is_null()) {
        out.reset();
        return;
    }
    T value{};
    read_json(name, j, value);
    out = value;
}

// --- command line -------------------------------------------------------------------

// Values as text, exactly: doubles with 17 significant digits read back bit for bit.
inline std::string text(const std::string& s) { return s; }
inline std::string text(char c) { return std::string(1, c); }
inline std::string text(bool b) { return b ? "1" : "0"; }
template <std::integral I>
std::string text(I i) {
    return std::to_string(i);
}
inline std::string text(double d) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", d);
    return buf;
}
template <NamedEnum E>
std::string text(E e) {
    return name_of(e);
}
template <class T, size_t N>
std::string text(const std::array<T, N>& a) {
    std::string s;
    for (size_t i = 0; i < N; ++i) s += (i ? "," : "") + text(a[i]);
    return s;
}

template <std::integral I>
void read_text(std::string_view name, std::string_view s, I& out) {
    if constexpr (std::same_as<I, bool>) {
        if (s != "0" && s != "1") malformed(name, s);
        out = s == "1";
    } else if constexpr (std::same_as<I, char>) {
        if (s.size() != 1) malformed(name, s);
        out = s[0];
    } else {
        auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
        if (ec != std::errc() || end != s.data() + s.size()) malformed(name, s);
    }
}
inline void read_text(std::string_view name, std::string_view s, double& out) {
    const std::string copy(s);
    char* end = nullptr;
    out = std::strtod(copy.c_str(), &end);
    if (copy.empty() || end != copy.c_str() + copy.size()) malformed(name, s);
}
inline void read_text(std::string_view, std::string_view s, std::string& out) { out = s; }
template <NamedEnum E>
void read_text(std::string_view name, std::string_view s, E& out) {
    const auto e = named<E>(s);
    if (!e) malformed(name, s);
    out = *e;
}
template <class T, size_t N>
void read_text(std::string_view name, std::string_view s, std::array<T, N>& out) {
    size_t start = 0;
    for (size_t i = 0; i < N; ++i) {
        const size_t comma = i + 1 < N ? s.find(',', start) : s.size();
        if (comma == s.npos || (i + 1 == N && s.find(',', start) != s.npos))
            malformed(name, s);
        read_text(name, s.substr(start, comma - start), out[i]);
        start = comma + 1;
    }
}

template <class T>
void write_arg(std::vector<std::string>& args, const char* name, const T& v) {
    args.push_back("--" + std::string(name) + "=" + text(v));
}
template <class T>
void write_arg(std::vector<std::string>& args, const char* name,
               const std::optional<T>& v) {
    if (v) write_arg(args, name, *v);
}
// Lists and maps: one argument per entry (none when empty).
template <class T>
void write_arg(std::vector<std::string>& args, const char* name,
               const std::vector<T>& v) {
    for (const T& e : v) write_arg(args, name, e);
}
template <class T>
void write_arg(std::vector<std::string>& args, const char* name,
               const std::map<std::string, T>& v) {
    for (const auto& [key, value] : v) write_arg(args, name, key + "=" + text(value));
}

template <class T>
void read_arg(std::string_view name, std::string_view s, T& out) {
    read_text(name, s, out);
}
template <class T>
void read_arg(std::string_view name, std::string_view s, std::optional<T>& out) {
    T value{};  // (not out.emplace(): clang reads a nested struct with member
                // initialisers as not default-constructible there)
    read_text(name, s, value);
    out = value;
}
template <class T>
void read_arg(std::string_view name, std::string_view s, std::vector<T>& out) {
    T value{};
    read_text(name, s, value);
    out.push_back(std::move(value));
}
template <class T>
void read_arg(std::string_view name, std::string_view s, std::map<std::string, T>& out) {
    const size_t eq = s.find('=');
    if (eq == s.npos || eq == 0) malformed(name, s);
    read_text(name, s.substr(eq + 1), out[std::string(s.substr(0, eq))]);
}

}  // namespace job_fields_detail

// Calls v(name, field) for every leaf field of `job`, nested jobs flattened.
template <class Job, class Visit>
void visit_job_fields(Job& job, Visit&& v) {
    using Plain = std::remove_const_t<Job>;
    Plain::fields(job, [&](const char* name, auto& field) {
        using Field = std::remove_cvref_t<decltype(field)>;
        if constexpr (JobFields<Field>) {
            visit_job_fields(field, v);
        } else {
            v(name, field);
        }
    });
}

// Adds the job's fields to `j` (an object).
template <JobFields Job>
void job_to_json(const Job& job, nlohmann::json& j) {
    visit_job_fields(job, [&](const char* name, const auto& field) {
        j[name] = job_fields_detail::json_of(field);
    });
}

template <JobFields Job>
nlohmann::json job_to_json(const Job& job) {
    nlohmann::json j = nlohmann::json::object();
    job_to_json(job, j);
    return j;
}

// Every field must be present (nlohmann::json::out_of_range names a missing one); keys
// of other fields are ignored (the message's type, a sibling job's fields).
template <JobFields Job>
void job_from_json(const nlohmann::json& j, Job& job) {
    visit_job_fields(job, [&](const char* name, auto& field) {
        job_fields_detail::read_json(name, j.at(name), field);
    });
}

// --name=value arguments; fields at their default... are written too (but an empty list
// or an unset optional writes nothing).
template <JobFields Job>
void job_to_argv(const Job& job, std::vector<std::string>& args) {
    visit_job_fields(job, [&](const char* name, const auto& field) {
        job_fields_detail::write_arg(args, name, field);
    });
}

// Reads --name=value arguments over `job` (fields not given keep their value); an
// argument that is no field of the job, or a malformed value, throws JobArgumentError.
template <JobFields Job>
void job_from_argv(const std::vector<std::string>& args, size_t first, Job& job) {
    for (size_t i = first; i < args.size(); ++i) {
        const std::string_view a = args[i];
        const size_t eq = a.find('=');
        if (a.substr(0, 2) != "--" || eq == a.npos)
            throw JobArgumentError("unexpected argument '" + args[i] + "'");
        const std::string_view name = a.substr(2, eq - 2), value = a.substr(eq + 1);
        bool known = false;
        visit_job_fields(job, [&](const char* n, auto& field) {
            if (known || name != n) return;
            known = true;
            job_fields_detail::read_arg(name, value, field);
        });
        if (!known) throw JobArgumentError("unknown setting '" + args[i] + "'");
    }
}

}  // namespace povwall::distrib
