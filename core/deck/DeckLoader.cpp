#include "core/deck/DeckLoader.h"

#include <pugixml.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace tephra {

namespace fs = std::filesystem;

namespace {

// 1-based line of a byte offset in the source text.
int line_of(const std::string& source, ptrdiff_t offset) {
  if (offset < 0) return 0;
  offset = std::min<ptrdiff_t>(offset, static_cast<ptrdiff_t>(source.size()));
  return 1 + static_cast<int>(std::count(source.begin(), source.begin() + offset, '\n'));
}

struct Loader {
  std::vector<std::string> files;
  std::vector<std::string> stack;  // include chain, for cycle detection

  // Parses `source` (read from `file`) and returns its root element as a DeckNode.
  DeckNode parse(const std::string& source, const std::string& file, const fs::path& dir) {
    pugi::xml_document doc;
    pugi::xml_parse_result r = doc.load_buffer(source.data(), source.size(),
                                               pugi::parse_default, pugi::encoding_auto);
    if (!r) {
      std::string why = std::string("malformed XML: ") + r.description();
      // A symbolic link checked out as a plain file (git without symlink
      // support) holds just the target path: say so instead of only "no
      // document element".
      const std::string trimmed = source.substr(0, source.find_last_not_of(" \t\r\n") + 1);
      if (!trimmed.empty() && trimmed.size() < 4096 && trimmed.find('<') == std::string::npos &&
          trimmed.find('\n') == std::string::npos)
        why += "; the file holds only the text '" + trimmed +
               "' (a symbolic link stored as a plain file? open the file it names)";
      throw DeckError({file, line_of(source, r.offset), ""}, why);
    }
    pugi::xml_node root = doc.document_element();
    if (!root) throw DeckError({file, 1, ""}, "no root element");
    DeckNode out;
    convert(root, out, source, file, dir);
    return out;
  }

  void convert(const pugi::xml_node& x, DeckNode& out, const std::string& source,
               const std::string& file, const fs::path& dir) {
    out.name = x.name();
    out.file = file;
    out.line = line_of(source, x.offset_debug());
    std::string text;
    for (pugi::xml_node c = x.first_child(); c; c = c.next_sibling())
      if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) text += c.value();
    out.text = trim(text);
    for (pugi::xml_attribute a = x.first_attribute(); a; a = a.next_attribute())
      out.attributes.emplace_back(a.name(), trim(a.value()));
    for (pugi::xml_node c = x.first_child(); c; c = c.next_sibling()) {
      if (c.type() != pugi::node_element) continue;
      if (std::string(c.name()) == "include") {
        include(c, out, source, file, dir);
        continue;
      }
      out.children.emplace_back();
      convert(c, out.children.back(), source, file, dir);
    }
  }

  void include(const pugi::xml_node& inc, DeckNode& parent, const std::string& source,
               const std::string& file, const fs::path& dir) {
    SourceLocation where{file, line_of(source, inc.offset_debug()), "include"};
    std::string href = trim(inc.attribute("href").value());
    if (href.empty()) throw DeckError(where, "<include> needs an href attribute");
    fs::path found = resolve(href, dir);
    if (found.empty())
      throw DeckError(where, "included file '" + href + "' not found next to " + dir.string() +
                                 " nor relative to any of its parent folders");
    std::string canon = fs::weakly_canonical(found).string();
    if (std::find(stack.begin(), stack.end(), canon) != stack.end())
      throw DeckError(where, "include cycle: '" + href + "' includes itself");
    std::string text = read_file(found, where);
    files.push_back(found.string());
    stack.push_back(canon);
    DeckNode inc_root = parse(text, found.string(), found.parent_path());
    stack.pop_back();
    for (auto& c : inc_root.children) parent.children.push_back(std::move(c));
  }

  static fs::path resolve(const std::string& href, const fs::path& dir) {
    fs::path h(href);
    if (h.is_absolute()) return fs::is_regular_file(h) ? h : fs::path();
    fs::path d = dir.empty() ? fs::current_path() : fs::absolute(dir);
    while (true) {
      fs::path candidate = d / h;
      std::error_code ec;
      if (fs::is_regular_file(candidate, ec)) return candidate.lexically_normal();
      if (!d.has_parent_path() || d.parent_path() == d) break;
      d = d.parent_path();
    }
    return {};
  }

  static std::string read_file(const fs::path& p, const SourceLocation& where) {
    std::ifstream in(p, std::ios::binary);
    if (!in) throw DeckError(where, "cannot read file '" + p.string() + "'");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
};

std::unique_ptr<Deck> finish(Loader& L, DeckNode root, const std::string& path) {
  auto deck = std::make_unique<Deck>();
  deck->root = std::move(root);
  deck->root.finalize_parents();
  deck->path = path;
  deck->files = L.files;
  if (deck->root.name != "Uintah_specification")
    throw DeckError({path, deck->root.line, deck->root.name},
                    "the root element must be <Uintah_specification>");
  return deck;
}

}  // namespace

std::unique_ptr<Deck> load_deck(const std::string& path) {
  fs::path p(path);
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) throw DeckError({path, 0, ""}, "deck file not found");
  Loader L;
  std::string text = Loader::read_file(p, {path, 0, ""});
  L.files.push_back(path);
  L.stack.push_back(fs::weakly_canonical(p).string());
  DeckNode root = L.parse(text, path, p.parent_path());
  return finish(L, std::move(root), path);
}

std::unique_ptr<Deck> load_deck_from_string(const std::string& xml, const std::string& name,
                                            const std::string& base_dir) {
  Loader L;
  L.files.push_back(name);
  DeckNode root = L.parse(xml, name, base_dir);
  return finish(L, std::move(root), name);
}

namespace {
void write_node(const DeckNode& n, pugi::xml_node parent) {
  pugi::xml_node x = parent.append_child(n.name.c_str());
  for (const auto& [k, v] : n.attributes) x.append_attribute(k.c_str()) = v.c_str();
  if (!n.text.empty()) x.append_child(pugi::node_pcdata).set_value(n.text.c_str());
  for (const auto& c : n.children) write_node(c, x);
}
}  // namespace

std::string to_xml(const DeckNode& root) {
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  write_node(root, doc);
  std::ostringstream s;
  doc.save(s, "  ");
  return s.str();
}

}  // namespace tephra
