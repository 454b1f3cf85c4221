// The gmsh reader (gmsh_mesh.h): the sections of versions 2.2 and 4.1 into raw nodes and
// elements (this file), then the cells checked, turned over where needed, and the faces matched
// to them (gmsh_cells.cc).

#include "mesh/gmsh_mesh.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <utility>

#include "bearing/errors.h"
#include "mesh/gmsh_raw.h"
#include "mesh/gmsh_text.h"

namespace bearing::fem {

namespace {

using gmsh::kMaxNodeTag;
using gmsh::kMaxTag;
using gmsh::Lines;
using gmsh::RawMesh;
using gmsh::Tokens;

// At most this many entries are reserved for a count the file claims (the rest grows as read):
// a claim alone never allocates much.
std::size_t reserve_for(long long claim, std::size_t text_size) {
  return static_cast<std::size_t>(
      std::min<long long>(claim, static_cast<long long>(text_size / 8)));
}

// The line after a section's content must end it.
void expect_end(Lines& lines, const std::string& section) {
  const std::string end = "$End" + section;
  const std::string_view line = lines.require(end.c_str());
  Tokens t(line, lines);
  if (t.empty() || t.word("") != end)
    lines.fail("expected " + end + " (more entries than the section's count says?), found \"" +
               Tokens::shown(line) + "\"");
}

std::string parse_format(Lines& lines) {
  Tokens t(lines.require("the format line (2.2 0 8 or 4.1 0 8)"), lines);
  const std::string version(t.word("the version"));
  const long long file_type = t.integer("the file type", 0, 1);
  const long long size = t.integer("the data size", 1, 64);
  t.finish("the format line");
  if (version != "2.2" && version != "4.1")
    lines.fail("MSH version " + Tokens::shown(version) +
               ": this reader reads versions 2.2 and 4.1 (gmsh -format msh22 or msh41)");
  if (file_type != 0)
    lines.fail(
        "a binary MSH file: this reader reads ASCII ones (gmsh: Mesh.Binary = 0, the default)");
  if (size != 8) lines.fail("data size " + std::to_string(size) + ": gmsh writes 8");
  expect_end(lines, "MeshFormat");
  return version;
}

void parse_names(Lines& lines, RawMesh& raw) {
  const long long n =
      Tokens(lines.require("the number of names"), lines).integer("the number of names", 0, 1e6);
  for (long long i = 0; i < n; ++i) {
    const std::string_view line = lines.require("a physical name");
    Tokens t(line, lines);
    PhysicalName p;
    p.dimension = static_cast<int>(t.integer("the dimension", 0, 3));
    p.tag = static_cast<int>(t.integer("the physical tag", 1, kMaxTag));
    const std::size_t open = line.find('"'), close = line.rfind('"');
    if (open == std::string_view::npos || close == open)
      lines.fail("a physical name must be written in double quotes");
    p.name = std::string(line.substr(open + 1, close - open - 1));
    Tokens(line.substr(close + 1), lines).finish("the name");
    for (const PhysicalName& q : raw.names)
      if (q.dimension == p.dimension && q.tag == p.tag)
        lines.fail("physical tag " + std::to_string(p.tag) + " of dimension " +
                   std::to_string(p.dimension) + " is named twice");
    raw.names.push_back(std::move(p));
  }
  expect_end(lines, "PhysicalNames");
}

// 4.1: each entity's physical tags (points have no bounding box, the others do and list their
// bounding entities after the tags).
void parse_entities(Lines& lines, RawMesh& raw) {
  Tokens head(lines.require("the numbers of entities"), lines);
  long long count[4];
  for (long long& c : count) c = head.integer("a number of entities", 0, 1e8);
  head.finish("the numbers of entities");
  for (int dim = 0; dim < 4; ++dim)
    for (long long i = 0; i < count[dim]; ++i) {
      Tokens t(lines.require("an entity"), lines);
      const int tag = static_cast<int>(t.integer("the entity tag", 1, kMaxTag));
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) t.real("a coordinate of the entity");
      const long long n_physical = t.integer("the number of physical tags", 0, 1e6);
      std::vector<int> physicals;
      for (long long k = 0; k < n_physical; ++k) {
        // gmsh writes a negative tag for a physical group of the opposite orientation.
        const long long p = t.integer("a physical tag", -kMaxTag, kMaxTag);
        if (p == 0) lines.fail("physical tag 0");
        physicals.push_back(static_cast<int>(p < 0 ? -p : p));
      }
      if (dim > 0) {
        const long long n_bounding = t.integer("the number of bounding entities", 0, 1e8);
        for (long long k = 0; k < n_bounding; ++k)
          t.integer("a bounding entity", -kMaxTag, kMaxTag);
      }
      t.finish("the entity");
      if (!raw.entity_physicals.emplace(std::make_pair(dim, tag), std::move(physicals)).second)
        lines.fail("entity " + std::to_string(tag) + " of dimension " + std::to_string(dim) +
                   " is defined twice");
    }
  expect_end(lines, "Entities");
}

void add_node(Lines& lines, RawMesh& raw, long long tag, const std::array<double, 3>& x) {
  if (!raw.node_index.emplace(tag, raw.nodes.size()).second)
    lines.fail("node " + std::to_string(tag) + " is defined twice");
  raw.nodes.push_back(x);
}

std::array<double, 3> read_point(Tokens& t) {
  return {t.real("the node's x"), t.real("the node's y"), t.real("the node's z")};
}

void parse_nodes_22(Lines& lines, RawMesh& raw, std::size_t text_size) {
  const long long n = Tokens(lines.require("the number of nodes"), lines)
                          .integer("the number of nodes", 0, kMaxNodeTag);
  raw.nodes.reserve(reserve_for(n, text_size));
  for (long long i = 0; i < n; ++i) {
    Tokens t(lines.require("a node"), lines);
    const long long tag = t.integer("the node tag", 1, kMaxNodeTag);
    const std::array<double, 3> x = read_point(t);
    t.finish("the node's coordinates");
    add_node(lines, raw, tag, x);
  }
  expect_end(lines, "Nodes");
}

void parse_nodes_41(Lines& lines, RawMesh& raw, std::size_t text_size) {
  Tokens head(lines.require("the node blocks' header"), lines);
  const long long blocks = head.integer("the number of node blocks", 0, kMaxNodeTag);
  const long long n = head.integer("the number of nodes", 0, kMaxNodeTag);
  head.integer("the smallest node tag", 0, kMaxNodeTag);
  head.integer("the largest node tag", 0, kMaxNodeTag);
  head.finish("the node blocks' header");
  raw.nodes.reserve(reserve_for(n, text_size));
  long long read = 0;
  std::vector<long long> tags;
  for (long long b = 0; b < blocks; ++b) {
    Tokens t(lines.require("a node block"), lines);
    const long long dim = t.integer("the block's dimension", 0, 3);
    t.integer("the block's entity tag", 1, kMaxTag);
    const long long parametric = t.integer("the parametric flag", 0, 1);
    const long long in_block = t.integer("the number of nodes in the block", 0, n - read);
    t.finish("the node block's header");
    tags.clear();
    for (long long i = 0; i < in_block; ++i) {
      Tokens tt(lines.require("a node tag"), lines);
      tags.push_back(tt.integer("the node tag", 1, kMaxNodeTag));
      tt.finish("the node tag");
    }
    for (long long i = 0; i < in_block; ++i) {
      Tokens tx(lines.require("a node's coordinates"), lines);
      const std::array<double, 3> x = read_point(tx);
      for (long long k = 0; parametric && k < dim; ++k) tx.real("a parametric coordinate");
      tx.finish("the node's coordinates");
      add_node(lines, raw, tags[static_cast<std::size_t>(i)], x);
    }
    read += in_block;
  }
  if (read != n)
    lines.fail("the node blocks hold " + std::to_string(read) + " nodes, the header says " +
               std::to_string(n));
  expect_end(lines, "Nodes");
}

void parse_elements_22(Lines& lines, RawMesh& raw) {
  const long long n = Tokens(lines.require("the number of elements"), lines)
                          .integer("the number of elements", 0, kMaxNodeTag);
  std::vector<long long> nodes;
  for (long long i = 0; i < n; ++i) {
    Tokens t(lines.require("an element"), lines);
    t.integer("the element tag", 1, kMaxNodeTag);
    const long long type = t.integer("the element type", 1, kMaxTag);
    const gmsh::ElementType& et = gmsh::element_type(type, lines);
    const long long n_tags = t.integer("the number of tags", 0, 1000);
    std::vector<int> physicals;
    for (long long k = 0; k < n_tags; ++k) {
      const long long tag = t.integer("a tag", -kMaxTag, kMaxTag);
      if (k == 0 && tag > 0) physicals.push_back(static_cast<int>(tag));  // the physical group
    }
    nodes.clear();
    for (int k = 0; k < et.nodes; ++k) nodes.push_back(t.integer("a node tag", 1, kMaxNodeTag));
    t.finish("the element's nodes");
    gmsh::add_element(lines, raw, type, nodes, physicals);
  }
  expect_end(lines, "Elements");
}

void parse_elements_41(Lines& lines, RawMesh& raw, bool have_entities) {
  Tokens head(lines.require("the element blocks' header"), lines);
  const long long blocks = head.integer("the number of element blocks", 0, kMaxNodeTag);
  const long long n = head.integer("the number of elements", 0, kMaxNodeTag);
  head.integer("the smallest element tag", 0, kMaxNodeTag);
  head.integer("the largest element tag", 0, kMaxNodeTag);
  head.finish("the element blocks' header");
  long long read = 0;
  std::vector<long long> nodes;
  for (long long b = 0; b < blocks; ++b) {
    Tokens t(lines.require("an element block"), lines);
    const long long dim = t.integer("the block's dimension", 0, 3);
    const int entity = static_cast<int>(t.integer("the block's entity tag", 1, kMaxTag));
    const long long type = t.integer("the element type", 1, kMaxTag);
    const long long in_block = t.integer("the number of elements in the block", 0, n - read);
    t.finish("the element block's header");
    const gmsh::ElementType& et = gmsh::element_type(type, lines);
    if (et.dimension != dim)
      lines.fail("a block of dimension " + std::to_string(dim) + " holds elements of type " +
                 std::to_string(type) + " (" + et.name + ")");
    const auto found = raw.entity_physicals.find({static_cast<int>(dim), entity});
    if (have_entities && found == raw.entity_physicals.end())
      lines.fail("entity " + std::to_string(entity) + " of dimension " + std::to_string(dim) +
                 " is not in $Entities");
    static const std::vector<int> none;
    const std::vector<int>& physicals = found == raw.entity_physicals.end() ? none : found->second;
    for (long long i = 0; i < in_block; ++i) {
      Tokens te(lines.require("an element"), lines);
      te.integer("the element tag", 1, kMaxNodeTag);
      nodes.clear();
      for (int k = 0; k < et.nodes; ++k) nodes.push_back(te.integer("a node tag", 1, kMaxNodeTag));
      te.finish("the element's nodes");
      gmsh::add_element(lines, raw, type, nodes, physicals);
    }
    read += in_block;
  }
  if (read != n)
    lines.fail("the element blocks hold " + std::to_string(read) + " elements, the header says " +
               std::to_string(n));
  expect_end(lines, "Elements");
}

// Skips an unknown section up to its $End line.
void skip_section(Lines& lines, const std::string& name) {
  const std::string end = "$End" + name;
  for (;;) {
    Tokens t(lines.require(end.c_str()), lines);
    if (!t.empty() && t.word("") == end) return;
  }
}

}  // namespace

GmshMesh parse_gmsh_mesh(std::string_view text, const std::string& file) {
  Lines lines(text, file);
  RawMesh raw;
  bool have_nodes = false, have_elements = false, have_entities = false;
  std::string_view line;
  while (lines.next(line)) {
    Tokens t(line, lines);
    if (t.empty()) continue;
    const std::string_view word = t.word("");
    if (raw.version.empty() && word != "$MeshFormat")
      lines.fail("a .msh file starts with $MeshFormat; found \"" + Tokens::shown(line) +
                 "\" (is this a gmsh mesh?)");
    if (word.front() != '$' || word.size() < 2)
      lines.fail("expected a section ($Nodes, $Elements, ...), found \"" + Tokens::shown(line) +
                 "\"");
    const std::string section(word.substr(1));
    if (section == "MeshFormat") {
      if (!raw.version.empty()) lines.fail("a second $MeshFormat");
      raw.version = parse_format(lines);
    } else if (section == "PhysicalNames") {
      parse_names(lines, raw);
    } else if (section == "Entities" && raw.version == "4.1") {
      if (have_entities) lines.fail("a second $Entities");
      parse_entities(lines, raw);
      have_entities = true;
    } else if (section == "PartitionedEntities") {
      lines.fail("a partitioned mesh: this reader reads whole meshes (gmsh: no Mesh.Partition)");
    } else if (section == "Nodes") {
      if (have_nodes) lines.fail("a second $Nodes");
      if (raw.version == "2.2")
        parse_nodes_22(lines, raw, text.size());
      else
        parse_nodes_41(lines, raw, text.size());
      have_nodes = true;
    } else if (section == "Elements") {
      if (have_elements) lines.fail("a second $Elements");
      if (!have_nodes) lines.fail("$Elements before $Nodes");
      if (raw.version == "2.2")
        parse_elements_22(lines, raw);
      else
        parse_elements_41(lines, raw, have_entities);
      have_elements = true;
    } else if (section.compare(0, 3, "End") == 0) {
      lines.fail("\"" + Tokens::shown(word) + "\" ends no section that was begun");
    } else {
      skip_section(lines, section);
    }
  }
  if (raw.version.empty()) throw InputError(file + ": empty, not a gmsh mesh (no $MeshFormat)");
  if (!have_elements)
    throw InputError(file +
                     ": no $Elements section: the file holds no mesh (gmsh -3 meshes the "
                     "volume)");
  return gmsh::finish_mesh(std::move(raw), file);
}

GmshMesh read_gmsh_mesh(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the mesh file");
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError(path + ": cannot read the mesh file");
  return parse_gmsh_mesh(text, path);
}

std::vector<unsigned int> mesh_parts(const GmshMesh& mesh, unsigned int& parts) {
  // Union-find on the vertices: each cell joins its vertices.
  std::vector<std::size_t> root(mesh.vertices.size());
  for (std::size_t v = 0; v < root.size(); ++v) root[v] = v;
  const auto find = [&](std::size_t v) {
    while (root[v] != v) v = root[v] = root[root[v]];
    return v;
  };
  for (const auto& c : mesh.cells)
    for (std::size_t k = 1; k < c.size(); ++k) root[find(c[k])] = find(c[0]);
  std::map<std::size_t, unsigned int> number;
  std::vector<unsigned int> part;
  for (const auto& c : mesh.cells)
    part.push_back(
        number.emplace(find(c[0]), static_cast<unsigned int>(number.size())).first->second);
  parts = static_cast<unsigned int>(number.size());
  return part;
}

std::vector<bool> parts_touching(const GmshMesh& mesh, const std::vector<unsigned int>& part,
                                 unsigned int parts, const std::vector<int>& tags) {
  std::vector<unsigned int> part_of_vertex(mesh.vertices.size(), 0);
  for (std::size_t c = 0; c < mesh.cells.size(); ++c)
    for (unsigned int v : mesh.cells[c]) part_of_vertex[v] = part[c];
  std::vector<bool> touching(parts, false);
  for (const MeshFace& f : mesh.faces)
    for (int t : tags)
      if (std::find(f.physicals.begin(), f.physicals.end(), t) != f.physicals.end())
        touching[part_of_vertex[f.vertices[0]]] = true;
  return touching;
}

int GmshMesh::surface_tag(std::string_view name) const {
  for (const PhysicalName& p : names)
    if (p.dimension == 2 && p.name == name) return p.tag;
  return 0;
}

std::string GmshMesh::surface_names() const {
  std::string s;
  for (const PhysicalName& p : names)
    if (p.dimension == 2) s += (s.empty() ? "\"" : ", \"") + p.name + "\"";
  return s.empty() ? "none" : s;
}

const char* GmshMesh::cell_type_name() const {
  return cell_type == CellType::tetrahedron ? "tetrahedron" : "hexahedron";
}

}  // namespace bearing::fem
