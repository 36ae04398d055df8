#pragma once
// Which pages may open the console's WebSocket: a browser sends the page's Origin with the
// upgrade request. Accepted: the console's own page (Origin "http://" or "https://" + the
// request's Host header, compared without case), an Origin listed in allowed_origins, or no
// Origin at all (not a browser: a tool like the integration test, which could send any Origin it
// likes; the control token, not the Origin, guards commands). Everything else ("null", another
// site, a port other than the Host's) is refused.

#include <string>
#include <vector>

namespace refloc {

enum class OriginVerdict { kAccepted, kRefused };

/// origin and host as the request carries them ("" = header absent).
OriginVerdict judge_origin(const std::string& origin, const std::string& host,
                           const std::vector<std::string>& allowed_origins);

}  // namespace refloc
