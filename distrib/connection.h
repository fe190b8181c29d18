// One TCP connection between povwall processes: whole frames in (on_frame), buffers out
// (send), on the process's one io_context thread. Every handler holds a shared_ptr to the
// connection, which owns its read buffer and its queue of outgoing buffers, so a buffer
// lives until its operation completes.
#pragma once

// clang-format off
#include <utility>  // before Asio: Boost 1.74 uses std::exchange without it
#include <boost/asio.hpp>
// clang-format on
#include <cstring>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "distrib/wire/control.h"
#include "distrib/wire/frame.h"

namespace povwall::distrib {

namespace asio = boost::asio;
using asio::ip::tcp;

// "disconnected (...)": a dead peer shows as end of file or as a reset, depending on
// unread data in its socket; both read as a lost connection.
std::string disconnected(const boost::system::error_code& ec);

class Connection : public std::enable_shared_from_this<Connection> {
  public:
    Connection(tcp::socket socket, std::string name)
        : socket_(std::move(socket)), name_(std::move(name)) {
        boost::system::error_code ec;
        socket_.set_option(tcp::no_delay(true), ec);
    }
    std::function<void(Frame&)> on_frame;
    std::function<void(const std::string&)> on_error;
    const std::string& name() const { return name_; }

    void start() { read(); }
    void send(Buffer buf) {  // io thread only
        if (closed_) return;
        queue_.push_back(std::move(buf));
        if (writing_ == 0) write();
    }
    void close() {
        closed_ = true;
        boost::system::error_code ec;
        socket_.shutdown(tcp::socket::shutdown_both, ec);
        socket_.close(ec);
    }
    bool closed() const { return closed_; }

  private:
    void read() {
        auto self = shared_from_this();
        // Received bytes land after the unparsed ones in `pending_` (kept at its largest
        // size, so no fresh pages per frame); parsed frames are dropped by moving only
        // the partial frame that follows them to the front.
        if (pending_size_ < filled_ + chunk_)
            grow_pending(std::max(2 * pending_size_, filled_ + chunk_));
        socket_.async_read_some(
            asio::buffer(pending_.get() + filled_, chunk_),
            [this, self](boost::system::error_code ec, size_t n) {
                if (closed_) return;
                if (ec) return fail(disconnected(ec));
                filled_ += n;
                if (n == chunk_) chunk_ = kChunk;  // a stream of items: read more at once
                size_t used = 0;
                for (;;) {
                    DecodeStatus st = decode_frame(
                        std::span(pending_.get() + used, filled_ - used), frame_);
                    if (st == DecodeStatus::NeedMore) break;
                    if (st == DecodeStatus::Bad)
                        return fail("malformed frame or wrong protocol version");
                    used += frame_.consumed;
                    on_frame(frame_);
                    if (closed_) return;
                }
                if (used) {
                    std::memmove(pending_.get(), pending_.get() + used, filled_ - used);
                    filled_ -= used;
                }
                read();
            });
    }
    // Everything queued goes out in one write (one system call for many small frames).
    void write() {
        auto self = shared_from_this();
        writing_ = queue_.size();
        gather_.clear();
        for (const Buffer& b : queue_) gather_.push_back(asio::buffer(*b));
        asio::async_write(
            socket_, gather_, [this, self](boost::system::error_code ec, size_t) {
                if (closed_) return;
                if (ec) return fail(disconnected(ec));
                queue_.erase(queue_.begin(), queue_.begin() + ptrdiff_t(writing_));
                writing_ = 0;
                if (!queue_.empty()) write();
            });
    }
    // Not zeroed: a page of it is first touched when bytes arrive there, so a connection
    // that only sends (or only receives control frames) never faults its 64 KB in.
    void grow_pending(size_t size) {
        auto grown = std::make_unique_for_overwrite<uint8_t[]>(size);
        if (filled_) std::memcpy(grown.get(), pending_.get(), filled_);
        pending_ = std::move(grown);
        pending_size_ = size;
    }
    void fail(const std::string& why) {
        if (closed_) return;
        close();
        if (on_error) on_error(why);
    }

    tcp::socket socket_;
    std::string name_;
    // Reads start small: most connections carry control frames only, or nothing (a
    // worker's connections to its peers only send); a full read goes up to kChunk.
    static constexpr size_t kChunk = 64 << 10;
    size_t chunk_ = 4 << 10;
    std::unique_ptr<uint8_t[]> pending_;
    size_t pending_size_ = 0;
    size_t filled_ = 0;  // bytes of pending_ received and not yet parsed
    Frame frame_;        // reused: its body keeps its capacity
    std::deque<Buffer> queue_;
    size_t writing_ = 0;  // buffers at the front of queue_ being written
    std::vector<asio::const_buffer> gather_;
    bool closed_ = false;
};

// HOST:PORT to an endpoint; throws DistribError when it does not resolve.
tcp::endpoint resolve(asio::io_context& io, const std::string& address);

}  // namespace povwall::distrib
