// The HTML report and the mold sheets: the data embedded in the page decode
// back to the result, the page lists one mold per tile with its instance count,
// and every sheet's lengths are the corner distances of an instance, its
// corners taken in the order the orientation gives (as the PLY's readers do).
// The command-line program writes both, and refuses bad paths before computing.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/IO/mold_sheet.h>
#include <CGAL/Tilable_surfaces/IO/report.h>
#include <CGAL/Tilable_surfaces/IO/write_HTML_report.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include "temp_dir.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace test_html_report_unit {

namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;
namespace fs = std::filesystem;
typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;

namespace {

// A translation surface: column i is the profile segment from x(i) to
// x(i + 1), swept along y, so the quads of a column are congruent and the
// columns differ: tilable at K = nx as it is. Face (i, j) lists its corners
// from corner (i + j) mod 4 on, so that the faces of a tile have different
// orientations.
Mesh swept_profile(int nx, int ny)
{
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i)
      v.push_back(m.add_vertex(Mesh::Point(i + 0.15 * i * i, 1.3 * j, 0.25 * i * i)));
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      const std::array<Mesh::Vertex_index, 4> c{{v[i + (nx + 1) * j], v[i + 1 + (nx + 1) * j],
                                                 v[i + 1 + (nx + 1) * (j + 1)], v[i + (nx + 1) * (j + 1)]}};
      const int s = (i + j) % 4;
      m.add_face(c[s], c[(s + 1) % 4], c[(s + 2) % 4], c[(s + 3) % 4]);
    }
  return m;
}

std::vector<unsigned char> base64_decoded(const std::string& text)
{
  std::vector<unsigned char> bytes;
  std::uint32_t word = 0;
  int bits = 0;
  for(char c : text)
  {
    const char* at = std::strchr("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/", c);
    if(c == '=' || at == nullptr) break;
    word = (word << 6) | std::uint32_t(at - "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/");
    bits += 6;
    if(bits >= 8) { bits -= 8; bytes.push_back((unsigned char)((word >> bits) & 0xff)); }
  }
  return bytes;
}

template <typename T>
std::vector<T> decoded(const nlohmann::json& data, const char* key)
{
  const std::vector<unsigned char> bytes = base64_decoded(data.at(key).get<std::string>());
  std::vector<T> values(bytes.size() / sizeof(T));
  EXPECT_EQ(values.size() * sizeof(T), bytes.size()) << key;
  std::memcpy(values.data(), bytes.data(), values.size() * sizeof(T));
  return values;
}

// The text of the <script> element with id `id`.
std::string script_text(const std::string& html, const std::string& id)
{
  const std::string open = "id=\"" + id + "\">";
  const std::size_t begin = html.find(open);
  EXPECT_NE(begin, std::string::npos) << id;
  const std::size_t start = begin + open.size();
  return html.substr(start, html.find("</script>", start) - start);
}

// Every value of the attribute `name` in the elements that start with `element`.
std::vector<std::string> attributes(const std::string& html, const std::string& element, const std::string& name)
{
  std::vector<std::string> values;
  const std::regex tag("<" + element + "[^>]*>");
  const std::regex attribute(" " + name + "=\"([^\"]*)\"");
  for(auto it = std::sregex_iterator(html.begin(), html.end(), tag); it != std::sregex_iterator(); ++it)
  {
    std::smatch m;
    const std::string text = it->str();
    if(std::regex_search(text, m, attribute)) values.push_back(m[1]);
  }
  return values;
}

std::vector<double> numbers(const std::string& text)
{
  std::istringstream in(text);
  std::vector<double> v;
  for(double x; in >> x;) v.push_back(x);
  return v;
}

// The corners of face `f` in the labelling of its tile: template corner i is
// face vertex (i + o) mod n for o < 4, (o - 4 - i) mod n otherwise.
std::vector<Mesh::Point> template_corners(const Mesh& m, Mesh::Face_index f, int o)
{
  std::vector<Mesh::Point> face;
  for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) face.push_back(m.point(v));
  const int n = int(face.size());
  std::vector<Mesh::Point> t;
  for(int i = 0; i < n; ++i) t.push_back(face[std::size_t(o < 4 ? (i + o) % n : ((o - 4 - i) % n + n) % n)]);
  return t;
}

// Each sheet's edges and diagonals against the corner distances of the first
// face of its tile, within 1e-9 relative.
template <typename ClusterOf, typename OrientationOf>
void check_sheet_lengths(const std::string& svg, const Mesh& m, ClusterOf cluster_of, OrientationOf orientation_of)
{
  const std::size_t tile = std::stoul(attributes(svg, "svg", "data-tile").at(0));
  const std::vector<double> edges = numbers(attributes(svg, "svg", "data-edges").at(0));
  const std::vector<double> diagonals = numbers(attributes(svg, "svg", "data-diagonals").at(0));
  for(auto f : faces(m))
  {
    if(std::size_t(cluster_of(f)) != tile) continue;
    const std::vector<Mesh::Point> t = template_corners(m, f, int(orientation_of(f)));
    ASSERT_EQ(edges.size(), t.size());
    auto distance = [&](std::size_t a, std::size_t b) { return std::sqrt(CGAL::squared_distance(t[a], t[b])); };
    for(std::size_t k = 0; k < t.size(); ++k)
      EXPECT_NEAR(edges[k], distance(k, (k + 1) % t.size()), 1e-9 * edges[k]) << "tile " << tile << " edge " << k;
    ASSERT_EQ(diagonals.size(), 2u);
    EXPECT_NEAR(diagonals[0], distance(0, 2), 1e-9 * diagonals[0]) << "tile " << tile;
    EXPECT_NEAR(diagonals[1], distance(1, 3), 1e-9 * diagonals[1]) << "tile " << tile;
    return;
  }
  ADD_FAILURE() << "no face of tile " << tile;
}

// Every <svg class="mold-sheet"> element of `html`.
std::vector<std::string> sheets_in(const std::string& html)
{
  std::vector<std::string> sheets;
  for(std::size_t at = html.find("<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"mold-sheet\""); at != std::string::npos;
      at = html.find("<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"mold-sheet\"", at + 1))
    sheets.push_back(html.substr(at, html.find("</svg>", at) + 6 - at));
  return sheets;
}

struct Tiled
{
  Mesh input, mesh;
  Mesh::Property_map<Mesh::Face_index, int> cluster, orientation;
  TS::K_set_tilable_result result;
};

Tiled tiled_profile()
{
  Tiled t;
  t.input = swept_profile(4, 3);
  t.mesh = t.input;
  t.cluster = t.mesh.add_property_map<Mesh::Face_index, int>("f:c", 0).first;
  t.orientation = t.mesh.add_property_map<Mesh::Face_index, int>("f:o", 0).first;
  t.result = TS::make_k_set_tilable(t.mesh, TSP::number_of_tiles(4).face_cluster_map(t.cluster)
                                                .face_orientation_map(t.orientation));
  return t;
}

std::string html_of(const Tiled& t, const nlohmann::json& report)
{
  std::ostringstream out;
  EXPECT_TRUE(TS::IO::write_HTML_report(out, t.mesh, t.input, t.result, report,
                                        TS::IO::HTML_viewer_scripts{"/* three */", "/* orbit */"},
                                        TSP::face_cluster_map(t.cluster).face_orientation_map(t.orientation)));
  return out.str();
}

} // namespace

TEST(HtmlReport, EmbeddedDataDecodeToTheResultAndEachTileIsListedWithItsInstances)
{
  const Tiled t = tiled_profile();
  ASSERT_TRUE(t.result.is_tilable());
  nlohmann::json report = TS::IO::tilability_report_json(t.result);
  report["input"] = {{"file", "profile</script><b>.off"}};
  const std::string html = html_of(t, report);
  EXPECT_EQ(html, html_of(t, report)) << "the same arguments give the same bytes";
  EXPECT_EQ(nlohmann::json::parse(script_text(html, "report-data")), report);

  const nlohmann::json data = nlohmann::json::parse(script_text(html, "mesh-data"));
  const std::vector<std::uint32_t> clusters = decoded<std::uint32_t>(data, "clusters");
  const std::vector<std::uint32_t> corners = decoded<std::uint32_t>(data, "face_vertices");
  const std::vector<float> points = decoded<float>(data, "positions"), input = decoded<float>(data, "input_positions");
  const std::vector<float> deviation = decoded<float>(data, "deviation");
  std::map<int, std::size_t> instances;
  std::size_t f_index = 0, corner = 0;
  for(auto f : faces(t.mesh))
  {
    ++instances[t.cluster[f]];
    EXPECT_EQ(clusters.at(f_index++), std::uint32_t(t.cluster[f]));
    for(auto v : CGAL::vertices_around_face(t.mesh.halfedge(f), t.mesh)) EXPECT_EQ(corners.at(corner++), std::uint32_t(v));
  }
  ASSERT_EQ(points.size(), 3 * t.mesh.number_of_vertices());
  for(auto v : vertices(t.mesh))
  {
    const Mesh::Point p = t.mesh.point(v), q = t.input.point(v);
    for(int a = 0; a < 3; ++a)
    {
      EXPECT_FLOAT_EQ(points[3 * v + a], float(p[a]));
      EXPECT_FLOAT_EQ(input[3 * v + a], float(q[a]));
    }
    // The vertex's own input position is on the input surface.
    EXPECT_GE(deviation[v], 0.0f);
    EXPECT_LE(deviation[v], float(std::sqrt(CGAL::squared_distance(p, q))) + 1e-6f);
  }

  const std::vector<std::string> tiles = attributes(html, "div class=\"mold\"", "data-tile");
  const std::vector<std::string> counts = attributes(html, "div class=\"mold\"", "data-instances");
  ASSERT_EQ(tiles.size(), instances.size());
  ASSERT_EQ(counts.size(), tiles.size());
  for(std::size_t i = 0; i < tiles.size(); ++i)
    EXPECT_EQ(std::stoul(counts[i]), instances.at(std::stoi(tiles[i]))) << "tile " << tiles[i];
  std::set<int> orientations;
  for(auto f : faces(t.mesh)) orientations.insert(t.orientation[f]);
  EXPECT_GE(orientations.size(), 2u) << "the corner labels are checked under several orientations";
  const std::vector<std::string> sheets = sheets_in(html);
  ASSERT_EQ(sheets.size(), instances.size());
  for(const std::string& svg : sheets)
    check_sheet_lengths(svg, t.mesh, [&](Mesh::Face_index f) { return t.cluster[f]; },
                        [&](Mesh::Face_index f) { return t.orientation[f]; });
}

TEST(HtmlReport, TheInputMustHaveTheResultsFaces)
{
  const Tiled t = tiled_profile();
  std::ostringstream out;
  EXPECT_THROW(TS::IO::write_HTML_report(out, t.mesh, swept_profile(4, 2), t.result, nlohmann::json::object(),
                                         TS::IO::HTML_viewer_scripts(),
                                         TSP::face_cluster_map(t.cluster).face_orientation_map(t.orientation)),
               TS::Invalid_input);
  EXPECT_TRUE(out.str().empty());
}

TEST(MoldSheet, ViewBoxInModelUnitsHoldsTheDrawingAndTheScaleBarIsRound)
{
  const Tiled t = tiled_profile();
  for(std::size_t i = 0; i < t.result.tiles.size(); ++i)
  {
    std::ostringstream out;
    ASSERT_TRUE(TS::IO::write_mold_sheet_SVG(out, t.result.tiles, i));
    const std::string svg = out.str();
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    const std::vector<double> box = numbers(attributes(svg, "svg", "viewBox").at(0));
    ASSERT_EQ(box.size(), 4u);
    for(const Eigen::Vector3d& p : t.result.tiles[i].corners)
    {
      EXPECT_GT(p.x(), box[0]); EXPECT_LT(p.x(), box[0] + box[2]);
      EXPECT_GT(-p.y(), box[1]); EXPECT_LT(-p.y(), box[1] + box[3]);
    }
    std::smatch bar;
    ASSERT_TRUE(std::regex_search(svg, bar, std::regex("class=\"scale-bar\" d=\"M\\S+ \\S+ v\\S+ h(\\S+) ")));
    const double length = std::stod(bar[1]), power = std::pow(10.0, std::floor(std::log10(length)));
    EXPECT_TRUE(std::abs(length / power - 1) < 1e-9 || std::abs(length / power - 2) < 1e-9 ||
                std::abs(length / power - 5) < 1e-9) << length;
  }
  // A directory lists the sheets in the order of the tiles.
  std::vector<std::string> names;
  for(const TS::Tile& tile : t.result.tiles) names.push_back(TS::IO::mold_sheet_file_name(tile));
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
}

// --- The command-line program -------------------------------------------

int run_program(const std::string& arguments, std::string& output)
{
  FILE* pipe = popen((std::string(K_SET_TILABLE_BINARY) + " " + arguments + " 2>&1").c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  std::array<char, 4096> buffer;
  output.clear();
  while(std::fgets(buffer.data(), int(buffer.size()), pipe)) output += buffer.data();
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(CommandLine, MoldSheetsMatchThePlyOrientationsAndTheHtmlListsEveryTile)
{
  Temp_dir dir("html_cli");
  const std::string off = (dir / "profile.off").string();
  ASSERT_TRUE(CGAL::IO::write_OFF(off, swept_profile(4, 3), CGAL::parameters::stream_precision(17)));
  const std::string html = (dir / "r.html").string(), sheets = (dir / "sheets").string(), ply = (dir / "r.ply").string();
  std::string output;
  const int code = run_program(off + " -k 4 -q -o " + ply + " --mold-sheets " + sheets + " --html " + html, output);
  const bool viewer = output.find("--html is not available in this build") == std::string::npos;
  if(!viewer)
  {
    EXPECT_EQ(code, 2) << output;
    EXPECT_FALSE(fs::exists(ply)) << "refused before the computation";
    ASSERT_EQ(run_program(off + " -k 4 -q -o " + ply + " --mold-sheets " + sheets, output), 0) << output;
  }
  else
    ASSERT_EQ(code, 0) << output;

  Mesh result;
  std::ifstream in(ply, std::ios::binary);
  ASSERT_TRUE(CGAL::IO::read_PLY(in, result));
  const auto read_cluster = result.property_map<Mesh::Face_index, int>("f:cluster");
  const auto read_orientation = result.property_map<Mesh::Face_index, std::uint8_t>("f:orientation");
  ASSERT_TRUE(read_cluster.second && read_orientation.second);
  const auto cluster = read_cluster.first;
  const auto orientation = read_orientation.first;
  std::set<int> ids, orientations;
  for(auto f : faces(result)) { ids.insert(cluster[f]); orientations.insert(orientation[f]); }
  EXPECT_GE(orientations.size(), 2u) << "the corner labels are checked under several orientations";
  std::size_t files = 0;
  for(const auto& entry : fs::directory_iterator(sheets))
  {
    ++files;
    std::ifstream sheet(entry.path());
    const std::string svg((std::istreambuf_iterator<char>(sheet)), std::istreambuf_iterator<char>());
    check_sheet_lengths(svg, result, [&](Mesh::Face_index f) { return cluster[f]; },
                        [&](Mesh::Face_index f) { return orientation[f]; });
  }
  EXPECT_EQ(files, ids.size());
  if(viewer)
  {
    std::ifstream page(html);
    const std::string text((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
    EXPECT_EQ(attributes(text, "div class=\"mold\"", "data-tile").size(), ids.size());
    EXPECT_NE(script_text(text, "three-module").find("three"), std::string::npos);
  }
}

TEST(CommandLine, BadHtmlAndSheetPathsAreRefusedBeforeComputing)
{
  Temp_dir dir("html_cli_bad");
  const std::string off = (dir / "profile.off").string(), ply = (dir / "r.ply").string();
  ASSERT_TRUE(CGAL::IO::write_OFF(off, swept_profile(2, 2)));
  std::ofstream(dir / "a_file") << "x";
  const std::vector<std::pair<std::string, std::string> > cases{
    {"--html " + (dir / "r.txt").string(), "must end in .html"},
    {"--html " + (dir / "missing" / "r.html").string(), "cannot create"},
    {"--mold-sheets " + (dir / "a_file").string(), "is not a directory"},
    {"--mold-sheets " + (dir / "missing" / "sheets").string(), "cannot create the directory"}};
  for(const auto& c : cases)
  {
    std::string output;
    EXPECT_EQ(run_program(off + " -k 2 -o " + ply + " " + c.first, output), 2) << c.first;
    EXPECT_NE(output.find(c.second), std::string::npos) << c.first << ": " << output;
    EXPECT_FALSE(fs::exists(ply)) << c.first;
  }
  std::string output;
  EXPECT_EQ(run_program(off + " --sweep 1:2 --curve " + (dir / "c.csv").string() + " --mold-sheets " +
                          (dir / "sheets").string(), output), 2);
  EXPECT_FALSE(fs::exists(dir / "missing"));
  EXPECT_FALSE(fs::exists(dir / "sheets"));
}

TEST(CommandLine, ASweepWritesThePageOfItsCurve)
{
  Temp_dir dir("html_cli_sweep");
  const std::string off = (dir / "profile.off").string(), csv = (dir / "c.csv").string();
  ASSERT_TRUE(CGAL::IO::write_OFF(off, swept_profile(3, 2)));
  std::string output;
  ASSERT_EQ(run_program(off + " -q --sweep 1:3 --curve " + csv + " --html " + (dir / "c.html").string(), output), 0)
    << output;
  std::ifstream page(dir / "c.html");
  const std::string html((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
  EXPECT_EQ(attributes(html, "tr class=\"trial\"", "data-k"), (std::vector<std::string>{"1", "2", "3"}));
  EXPECT_EQ(attributes(html, "circle class=\"trial\"", "data-k").size(), 3u);
  // The CSV the same run wrote says which K are tilable; the table says the same.
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> from_csv, from_table;
  while(std::getline(in, line))
  {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for(std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    from_csv.push_back(cells.at(0) + (cells.at(6) == "1" ? " yes" : " no"));
  }
  const std::regex row("<tr class=\"trial\" data-k=\"(\\d+)\">(<td>[^<]*</td>){5}<td>(yes|no)</td>");
  for(auto it = std::sregex_iterator(html.begin(), html.end(), row); it != std::sregex_iterator(); ++it)
    from_table.push_back((*it)[1].str() + " " + (*it)[3].str());
  EXPECT_EQ(from_table, from_csv);
  EXPECT_EQ(nlohmann::json::parse(script_text(html, "report-data"))["tried_K"].size(), 3u);
}

TEST(HtmlCurveReport, OneRowAndOneDotPerKTriedInTheirOrder)
{
  std::vector<TS::Tile_count_trial> trials(3);
  const std::size_t k[3] = {16, 8, 12};
  for(std::size_t i = 0; i < 3; ++i)
  {
    trials[i].number_of_tiles = k[i];
    trials[i].hausdorff_distance = 0.01 * double(i + 1);
    trials[i].is_tilable = i != 1;
  }
  std::ostringstream out;
  ASSERT_TRUE(TS::IO::write_HTML_curve_report(out, trials));
  const std::string html = out.str();
  EXPECT_EQ(attributes(html, "tr class=\"trial\"", "data-k"), (std::vector<std::string>{"16", "8", "12"}));
  const std::vector<std::string> dots = attributes(html, "circle class=\"trial\"", "data-k");
  EXPECT_EQ(dots, (std::vector<std::string>{"8", "12", "16"})) << "the plot goes by K";
  EXPECT_EQ(html.find("three-module"), std::string::npos) << "no 3D view";
}

} // namespace test_html_report_unit
