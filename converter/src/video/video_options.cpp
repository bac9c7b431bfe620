// Option values of the video painter: flow methods.
#include "video/video_paint.hpp"

namespace spt::video {

bool parse_flow_method(const std::string& s, FlowMethod& out) {
    if (s == "dis-ultrafast" || s == "dis") out = FlowMethod::DisUltrafast;
    else if (s == "dis-fast") out = FlowMethod::DisFast;
    else if (s == "dis-medium") out = FlowMethod::DisMedium;
    else if (s == "farneback") out = FlowMethod::Farneback;
    else return false;
    return true;
}

const char* flow_method_name(FlowMethod m) {
    switch (m) {
        case FlowMethod::DisUltrafast: return "dis-ultrafast";
        case FlowMethod::DisFast: return "dis-fast";
        case FlowMethod::DisMedium: return "dis-medium";
        case FlowMethod::Farneback: return "farneback";
    }
    return "?";
}

}  // namespace spt::video
