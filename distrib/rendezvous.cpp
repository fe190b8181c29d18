// Workers started by a launcher (mpirun, srun): each finds its rank in the environment,
// and rank 0 gathers the others' addresses before the render.
#include <fcntl.h>
#include <malloc.h>
#include <sched.h>
#include <signal.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <thread>
#include <unordered_map>

#include "core/memory.h"
#include "distrib/box_host.h"
#include "distrib/child_process.h"
#include "distrib/connection.h"
#include "distrib/distribution_plan.h"
#include "distrib/shared_pixel_sums.h"
#include "distrib/stats_json.h"
#include "distrib/tcp.h"
#include "distrib/wire/control.h"
#include "distrib/wire/items.h"
#include "distrib/wire/messages.h"
#include "distrib/wire/pixels.h"
#include "parser/parser.h"
#include "trace/pattern.h"

namespace povwall::distrib {

namespace {
// (In the unnamed namespace, as the other distrib files have them: a unity batch then
// declares the same aliases once more rather than shadowing them.)
using json = nlohmann::json;
using Clock = std::chrono::steady_clock;
}  // namespace

std::vector<uint8_t> encode_control_frame(const std::string& text) {
    std::vector<uint8_t> out;
    encode_frame(FrameType::Control, 0,
                 {reinterpret_cast<const uint8_t*>(text.data()), text.size()}, out);
    return out;
}

std::optional<LauncherRank> launcher_rank(
    const std::function<const char*(const char*)>& getenv) {
    auto number = [&](const char* name, int& out) {
        const char* v = getenv(name);
        if (!v || !*v) return false;
        char* end = nullptr;
        errno = 0;
        long n = std::strtol(v, &end, 10);
        if (*end || errno || n < 0 || n > 1'000'000)
            throw DistribError(std::string(name) + "='" + v +
                               "' is not a rank or a size");
        out = int(n);
        return true;
    };
    struct Pair {
        const char* rank;
        const char* size;
    };
    // srun's step task count first: SLURM_NTASKS is the allocation's.
    for (Pair p : {Pair{"SLURM_PROCID", "SLURM_STEP_NUM_TASKS"},
                   Pair{"SLURM_PROCID", "SLURM_NTASKS"},
                   Pair{"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"},
                   Pair{"PMI_RANK", "PMI_SIZE"}}) {
        LauncherRank r;
        if (!number(p.rank, r.rank) || !number(p.size, r.size)) continue;
        r.source = std::string(p.rank) + "/" + p.size;
        if (r.size < 1 || r.rank >= r.size)
            throw DistribError(std::string(p.rank) + "=" + std::to_string(r.rank) +
                               " is not below " + p.size + "=" + std::to_string(r.size));
        return r;
    }
    return std::nullopt;
}

std::vector<std::string> gather_workers(
    const std::string& address, const std::string& token, double timeout_seconds,
    const std::function<void(const std::string&)>& listening) {
    asio::io_context io;
    tcp::endpoint ep = resolve(io, address);
    tcp::acceptor acceptor(io);
    boost::system::error_code ec;
    acceptor.open(ep.protocol(), ec);
    if (!ec) acceptor.set_option(tcp::acceptor::reuse_address(true), ec);
    if (!ec) acceptor.bind(ep, ec);
    if (!ec) acceptor.listen(asio::socket_base::max_listen_connections, ec);
    if (ec)
        throw DistribError("cannot listen on rendezvous " + address + ": " +
                           ec.message());
    const tcp::endpoint bound = acceptor.local_endpoint();
    const std::string shown =
        bound.address().to_string() + ":" + std::to_string(bound.port());
    if (listening) listening(shown);

    std::vector<std::string> by_rank;
    int size = 0, registered = 0;
    std::string error;
    std::vector<std::shared_ptr<Connection>> connections;
    auto on_register = [&](const std::shared_ptr<Connection>& conn, Frame& f) {
        std::optional<RegisterMessage> reg;
        if (f.type == FrameType::Control) {
            const json j = parse_control(f);
            if (control_type(j) == RegisterMessage::kType) {
                try {
                    reg = read_message<RegisterMessage>(j);
                } catch (const json::exception&) {
                }
            }
        }
        if (!reg || reg->token != token) {
            std::fprintf(stderr,
                         "povwall: rejected a registration from %s: no valid job token\n",
                         conn->name().c_str());
            conn->close();
            return;
        }
        const int rank = int(reg->rank), n = int(reg->size);
        const std::string where = reg->address;
        if (size == 0 && n >= 1 && n <= 4096) {
            size = n;
            by_rank.assign(size_t(n), std::string());
        }
        if (size == 0) {
            error = "a worker registered a launch size of " + std::to_string(n) +
                    " (1 to 4096)";
        } else if (n != size) {
            error = "workers disagree on the launch size (" + std::to_string(size) +
                    " and " + std::to_string(n) + ")";
        } else if (rank < 0 || rank >= size) {
            error = "a worker registered as rank " + std::to_string(rank) + " of " +
                    std::to_string(size);
        } else if (!by_rank[size_t(rank)].empty()) {
            error = "two workers registered as rank " + std::to_string(rank) + " (" +
                    by_rank[size_t(rank)] + " and " + where + ")";
        } else {
            by_rank[size_t(rank)] = where;
            if (++registered < size) return;
        }
        io.stop();
    };
    std::function<void()> accept = [&] {
        acceptor.async_accept([&](boost::system::error_code aec, tcp::socket socket) {
            if (aec) return;
            boost::system::error_code pe;
            auto rep = socket.remote_endpoint(pe);
            std::string peer =
                pe ? "?" : rep.address().to_string() + ":" + std::to_string(rep.port());
            auto conn = std::make_shared<Connection>(std::move(socket), peer);
            std::weak_ptr<Connection> weak = conn;
            conn->on_frame = [&, weak](Frame& f) {
                if (auto c = weak.lock()) on_register(c, f);
            };
            conn->on_error = [](const std::string&) {};
            conn->start();
            connections.push_back(conn);
            accept();
        });
    };
    accept();
    io.run_for(std::chrono::milliseconds(long(timeout_seconds * 1000)));
    for (auto& c : connections) c->close();
    if (!error.empty()) throw DistribError("rendezvous " + shown + ": " + error);
    if (size == 0 || registered < size) {
        std::string missing;
        for (int r = 0; r < size; ++r) {
            if (!by_rank[size_t(r)].empty()) continue;
            missing += (missing.empty() ? "" : ", ") + std::to_string(r);
        }
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%g", timeout_seconds);
        throw DistribError(
            size == 0
                ? "rendezvous " + shown + ": no worker registered within " + seconds +
                      " s"
                : "rendezvous " + shown + ": only " + std::to_string(registered) +
                      " of " + std::to_string(size) + " workers registered within " +
                      seconds + " s (missing ranks: " + missing + ")");
    }
    return by_rank;
}

}  // namespace povwall::distrib
