#include "distrib/connection.h"

#include "distrib/tcp.h"

namespace povwall::distrib {

std::string disconnected(const boost::system::error_code& ec) {
    if (ec == asio::error::eof || ec == asio::error::connection_reset ||
        ec == asio::error::broken_pipe)
        return "disconnected (connection lost)";
    return "disconnected (" + ec.message() + ")";
}

tcp::endpoint resolve(asio::io_context& io, const std::string& address) {
    auto colon = address.rfind(':');
    if (colon == std::string::npos)
        throw DistribError("bad address '" + address + "' (HOST:PORT)");
    tcp::resolver resolver(io);
    boost::system::error_code ec;
    auto results =
        resolver.resolve(address.substr(0, colon), address.substr(colon + 1), ec);
    if (ec || results.empty())
        throw DistribError("cannot resolve '" + address + "': " + ec.message());
    return *results.begin();
}

}  // namespace povwall::distrib
