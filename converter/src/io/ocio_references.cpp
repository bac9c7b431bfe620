#include "io/ocio_references.hpp"

#include <yaml.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <memory>
#include <set>
#include <vector>

namespace spt::io {

namespace {

// An OCIO config is small; this bounds the parse of a file that is not one.
constexpr long kMaxConfigBytes = 16L << 20;
constexpr int kMaxDepth = 64;

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower((unsigned char)c));
    return s;
}

// The parsed document and lookups on it.
struct Doc {
    yaml_document_t d;
    yaml_node_t* node(int i) { return yaml_document_get_node(&d, i); }
    std::string scalar(yaml_node_t* n) {
        return n && n->type == YAML_SCALAR_NODE ? std::string((const char*)n->data.scalar.value, n->data.scalar.length) : "";
    }
    yaml_node_t* get(yaml_node_t* map, const char* key) {
        if (!map || map->type != YAML_MAPPING_NODE) return nullptr;
        for (yaml_node_pair_t* p = map->data.mapping.pairs.start; p < map->data.mapping.pairs.top; ++p)
            if (scalar(node(p->key)) == key) return node(p->value);
        return nullptr;
    }
    std::vector<yaml_node_t*> items(yaml_node_t* seq) {
        std::vector<yaml_node_t*> v;
        if (seq && seq->type == YAML_SEQUENCE_NODE)
            for (yaml_node_item_t* i = seq->data.sequence.items.start; i < seq->data.sequence.items.top; ++i)
                v.push_back(node(*i));
        return v;
    }
};

// The reference graph: nodes are "colour space 'x'", "look 'l'", ...; edges are references.
struct Graph {
    std::map<std::string, std::set<std::string>> edges;
    std::map<std::string, std::string> spaces;   // lower-case name, alias or role -> node
    std::map<std::string, std::string> looks;    // lower-case look name -> node
    std::map<std::string, std::string> views;    // lower-case "display/view" -> node
    std::map<std::string, std::string> view_transforms;
};

struct Walker {
    Doc& doc;
    Graph& g;
    // YAML aliases can make a small file a huge (or endless) tree: the walk has a budget.
    long budget = 4000000;
    // References found in `n` (a transform, or any value holding transforms) from `from`.
    void refs(const std::string& from, yaml_node_t* n, int depth) {
        if (!n || depth > kMaxDepth || --budget < 0) return;
        if (n->type == YAML_SEQUENCE_NODE) {
            for (yaml_node_t* i : doc.items(n)) refs(from, i, depth + 1);
            return;
        }
        if (n->type != YAML_MAPPING_NODE) return;
        for (yaml_node_pair_t* p = n->data.mapping.pairs.start; p < n->data.mapping.pairs.top; ++p) {
            const std::string key = doc.scalar(doc.node(p->key));
            yaml_node_t* v = doc.node(p->value);
            if (key == "src" || key == "dst") space_ref(from, doc.scalar(v));
            else if (key == "looks") look_refs(from, doc.scalar(v));
            else refs(from, v, depth + 1);
        }
        // A DisplayViewTransform goes through the view it names.
        const std::string display = doc.scalar(doc.get(n, "display")), view = doc.scalar(doc.get(n, "view"));
        if (!display.empty() && !view.empty()) g.edges[from].insert("view '" + display + "/" + view + "'");
    }
    void space_ref(const std::string& from, const std::string& name) {
        if (!name.empty()) g.edges[from].insert("@space:" + lower(name));
    }
    void look_refs(const std::string& from, const std::string& list) {
        // "+a, -b" or "a|b": names separated by , : | with a direction sign.
        std::string cur;
        auto flush = [&] {
            const size_t a = cur.find_first_not_of(" +-"), b = cur.find_last_not_of(' ');
            if (a != std::string::npos) g.edges[from].insert("@look:" + lower(cur.substr(a, b - a + 1)));
            cur.clear();
        };
        for (char c : list) {
            if (c == ',' || c == ':' || c == '|') flush();
            else cur += c;
        }
        flush();
    }
};

// The first loop of references (depth-first), as "a -> b -> a"; empty if none.
std::string find_loop(const Graph& g) {
    std::map<std::string, int> state;  // 1: on the path, 2: done
    std::vector<std::string> path;
    std::string loop;
    auto resolve = [&](const std::string& e) -> std::string {
        auto pick = [&](const std::map<std::string, std::string>& m, size_t skip) {
            auto it = m.find(e.substr(skip));
            return it == m.end() ? std::string() : it->second;
        };
        if (e.rfind("@space:", 0) == 0) return pick(g.spaces, 7);
        if (e.rfind("@look:", 0) == 0) return pick(g.looks, 6);
        return e;
    };
    // Iterative, so a config's own depth cannot overflow this stack either.
    for (const auto& [root, unused] : g.edges) {
        if (state[root]) continue;
        std::vector<std::pair<std::string, std::vector<std::string>>> stack;
        auto push = [&](const std::string& n) {
            state[n] = 1;
            path.push_back(n);
            std::vector<std::string> next;
            if (auto it = g.edges.find(n); it != g.edges.end())
                for (const std::string& e : it->second)
                    if (std::string r = resolve(e); !r.empty()) next.push_back(r);
            stack.push_back({n, std::move(next)});
        };
        push(root);
        while (!stack.empty() && loop.empty()) {
            auto& [n, next] = stack.back();
            if (next.empty()) {
                state[n] = 2;
                path.pop_back();
                stack.pop_back();
                continue;
            }
            const std::string m = next.back();
            next.pop_back();
            if (state[m] == 1) {
                for (auto it = std::find(path.begin(), path.end(), m); it != path.end(); ++it) loop += *it + " -> ";
                loop += m;
            } else if (state[m] == 0) {
                push(m);
            }
        }
        if (!loop.empty()) return loop;
    }
    return loop;
}

Status build_graph(Doc& doc, Graph& g, const std::string& path) {
    yaml_node_t* root = yaml_document_get_root_node(&doc.d);
    if (!root || root->type != YAML_MAPPING_NODE) return make_error(Code::Corrupt, "OCIO config '" + path + "': not a YAML mapping");
    Walker w{doc, g};
    // Colour spaces (scene and display) and named transforms share one namespace, with aliases.
    auto spaces = [&](const char* list, const char* kind) {
        for (yaml_node_t* cs : doc.items(doc.get(root, list))) {
            const std::string name = doc.scalar(doc.get(cs, "name"));
            if (name.empty()) continue;
            const std::string id = std::string(kind) + " '" + name + "'";
            g.spaces[lower(name)] = id;
            for (yaml_node_t* a : doc.items(doc.get(cs, "aliases"))) g.spaces[lower(doc.scalar(a))] = id;
            g.edges[id];
            for (const char* k : {"to_scene_reference", "from_scene_reference", "to_reference", "from_reference",
                                  "to_display_reference", "from_display_reference", "transform", "inverse_transform"})
                w.refs(id, doc.get(cs, k), 0);
        }
    };
    spaces("colorspaces", "colour space");
    spaces("display_colorspaces", "colour space");
    spaces("named_transforms", "named transform");
    // A role names a colour space (roles do not chain): it is another name of that space.
    if (yaml_node_t* roles = doc.get(root, "roles"); roles && roles->type == YAML_MAPPING_NODE)
        for (yaml_node_pair_t* p = roles->data.mapping.pairs.start; p < roles->data.mapping.pairs.top; ++p) {
            const std::string role = lower(doc.scalar(doc.node(p->key)));
            const auto target = g.spaces.find(lower(doc.scalar(doc.node(p->value))));
            if (target != g.spaces.end() && !g.spaces.count(role)) g.spaces[role] = target->second;
        }
    for (yaml_node_t* l : doc.items(doc.get(root, "looks"))) {
        const std::string name = doc.scalar(doc.get(l, "name"));
        if (name.empty()) continue;
        const std::string id = "look '" + name + "'";
        g.looks[lower(name)] = id;
        w.space_ref(id, doc.scalar(doc.get(l, "process_space")));
        w.refs(id, doc.get(l, "transform"), 0);
        w.refs(id, doc.get(l, "inverse_transform"), 0);
    }
    for (yaml_node_t* vt : doc.items(doc.get(root, "view_transforms"))) {
        const std::string name = doc.scalar(doc.get(vt, "name"));
        if (name.empty()) continue;
        const std::string id = "view transform '" + name + "'";
        g.view_transforms[lower(name)] = id;
        for (const char* k : {"to_scene_reference", "from_scene_reference", "to_display_reference", "from_display_reference"})
            w.refs(id, doc.get(vt, k), 0);
    }
    if (yaml_node_t* displays = doc.get(root, "displays"); displays && displays->type == YAML_MAPPING_NODE)
        for (yaml_node_pair_t* p = displays->data.mapping.pairs.start; p < displays->data.mapping.pairs.top; ++p) {
            const std::string display = doc.scalar(doc.node(p->key));
            for (yaml_node_t* v : doc.items(doc.node(p->value))) {
                const std::string id = "view '" + display + "/" + doc.scalar(doc.get(v, "name")) + "'";
                g.edges[id];
                w.space_ref(id, doc.scalar(doc.get(v, "colorspace")));
                w.space_ref(id, doc.scalar(doc.get(v, "display_colorspace")));
                w.look_refs(id, doc.scalar(doc.get(v, "looks")));
                const std::string vt = lower(doc.scalar(doc.get(v, "view_transform")));
                if (auto it = g.view_transforms.find(vt); it != g.view_transforms.end()) g.edges[id].insert(it->second);
            }
        }
    if (w.budget < 0) return make_error(Code::LimitExceeded, "OCIO config '" + path + "': its YAML aliases expand too far");
    return {};
}

}  // namespace

Status check_ocio_references(const std::string& path) {
    const std::string what = "OCIO config '" + path + "'";
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!f) return make_error(Code::IoError, what + ": cannot open it");
    if (std::fseek(f.get(), 0, SEEK_END) != 0 || std::ftell(f.get()) > kMaxConfigBytes)
        return make_error(Code::LimitExceeded, what + ": larger than 16 MiB");
    std::rewind(f.get());
    yaml_parser_t parser;
    if (!yaml_parser_initialize(&parser)) return make_error(Code::IoError, what + ": cannot start a YAML parser");
    yaml_parser_set_input_file(&parser, f.get());
    Doc doc;
    const bool loaded = yaml_parser_load(&parser, &doc.d) != 0;
    std::string err = parser.problem ? parser.problem : "";
    const size_t line = parser.problem_mark.line + 1;
    yaml_parser_delete(&parser);
    // Not YAML: OCIO says what is wrong with it when it loads it.
    if (!loaded) return make_error(Code::Corrupt, what + ": line " + std::to_string(line) + ": " + (err.empty() ? "not YAML" : err));
    Graph g;
    Status built = build_graph(doc, g, path);
    yaml_document_delete(&doc.d);
    if (!built) return built;
    if (std::string loop = find_loop(g); !loop.empty())
        return make_error(Code::Corrupt, what + ": its references go round in a loop (" + loop +
                                             "), which OpenColorIO would follow until it crashes");
    return {};
}

}  // namespace spt::io
