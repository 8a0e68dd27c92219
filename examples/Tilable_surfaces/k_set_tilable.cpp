// k_set_tilable: the command-line program for architects.
//
//   k_set_tilable INPUT (-k K | --max-deviation D [-k KMAX]) -o OUTPUT.ply
//                 [--report REPORT.json] [--catalog TILES.csv|TILES.json] [--curve CURVE.csv]
//                 [--components EDGES.ply] [--html REPORT.html] [--mold-sheets DIR]
//                 [--distance-weight W] [--fairness-weight W]
//                 [--tangential-weight W] [--optimized-candidates N] [--improvement-rounds N]
//                 [--candidates N] [--solver gauss-newton|paper-cg] [--fixed-boundary]
//                 [--iterations N] [--time-limit SECONDS] [--seed S] [--threads N] [--mirror]
//                 [--planar] [--panel-tolerance T | --panel-tolerance-relative t] [--ascii] [--quiet] [--help]
//   k_set_tilable INPUT --sweep KMIN:KMAX[:STEP] --curve CURVE.csv [--html CURVE.html] [options]
//
// Reads a quad mesh (OFF, OBJ or PLY), makes it K-set tilable, and writes the
// moved mesh (PLY with per-face cluster, orientation and colour), a JSON
// report of what was measured, and the tile catalog. With --max-deviation,
// K is the smallest whose result is tilable within D of the input; --sweep
// writes the K / deviation curve instead of a mesh. --html writes one
// self-contained page to open in a browser, --mold-sheets an SVG per tile.
// Exit codes: 0 done, 2 bad input or arguments (nothing written), 1 internal
// failure.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/IO/mold_sheet.h>
#include <CGAL/Tilable_surfaces/IO/read_polygon_mesh.h>
#include <CGAL/Tilable_surfaces/IO/report.h>
#include <CGAL/Tilable_surfaces/IO/tile_catalog.h>
#include <CGAL/Tilable_surfaces/IO/write_HTML_report.h>
#include <CGAL/Tilable_surfaces/IO/write_OBJ.h>
#include <CGAL/Tilable_surfaces/IO/write_PLY.h>
#include <CGAL/Tilable_surfaces/IO/write_edge_components_PLY.h>
#include <CGAL/Tilable_surfaces/IO/write_tile_count_curve.h>
#include <CGAL/Tilable_surfaces/k_set_tilable_curve.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>
#include <CGAL/Tilable_surfaces/mold_count_bounds.h>

#include <boost/program_options.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;
namespace po = boost::program_options;

namespace {

// A problem with the user's input or arguments: exit code 2.
struct Usage_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct Options
{
  std::string input, output, report, catalog, components, sweep, curve, html, mold_sheets;
  int k = 0;
  double max_deviation = -1; // negative: K is given
  std::vector<std::size_t> sweep_k;
  double distance_weight = TS::defaults::distance_weight;
  double fairness_weight = -1; // negative: the solver's default
  double tangential_weight = TS::defaults::tangential_weight;
  int optimized_candidates = -1; // negative: the package's default
  int improvement_rounds = TS::defaults::number_of_improvement_rounds;
  int candidates = int(TS::defaults::number_of_candidates), iterations = -1, threads = 0;
  double time_limit = -1; // negative: none
  // --panel-tolerance (model units) or --panel-tolerance-relative (of the
  // input's mean edge); panel_tolerance is set from either once the mesh is read.
  double panel_tolerance = 0, panel_tolerance_relative = 0;
  unsigned int seed = TS::defaults::random_seed;
  std::string solver = "gauss-newton";
  bool fixed_boundary = false, mirror = false, planar = false, ascii = false, quiet = false;
};

std::string extension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string e = path.substr(dot + 1);
  for(char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// KMIN:KMAX[:STEP] as the list of K.
std::vector<std::size_t> parse_sweep(const std::string& text)
{
  long long values[3] = {0, 0, 1};
  int count = 0;
  std::istringstream in(text);
  std::string field;
  while(std::getline(in, field, ':'))
  {
    std::size_t used = 0;
    try
    {
      if(count == 3)
        throw std::invalid_argument("too many fields");
      values[count++] = std::stoll(field, &used);
    }
    catch(const std::exception&)
    {
      used = std::string::npos;
    }
    if(used != field.size())
      throw Usage_error("--sweep '" + text + "' is not KMIN:KMAX[:STEP] with whole numbers");
  }
  if(count < 2 || values[0] < 1 || values[1] < values[0] || values[2] < 1)
    throw Usage_error("--sweep '" + text + "' must be KMIN:KMAX[:STEP] with 1 <= KMIN <= KMAX, STEP >= 1");
  std::vector<std::size_t> k;
  for(long long v = values[0]; v <= values[1]; v += values[2]) k.push_back(std::size_t(v));
  return k;
}

// --panel-tolerance and --panel-tolerance-relative: one at most, each a
// finite length >= 0.
void check_panel_tolerance(const po::variables_map& vm, const Options& o)
{
  if(vm.count("panel-tolerance") && vm.count("panel-tolerance-relative"))
    throw Usage_error("give --panel-tolerance T (model units) or --panel-tolerance-relative t (of the mean edge), "
                      "not both");
  if(!(std::isfinite(o.panel_tolerance) && o.panel_tolerance >= 0))
    throw Usage_error("--panel-tolerance must be a finite length >= 0 in model units");
  if(!(std::isfinite(o.panel_tolerance_relative) && o.panel_tolerance_relative >= 0))
    throw Usage_error("--panel-tolerance-relative must be a finite fraction >= 0 of the mean edge length");
}

// The options shown by --help, writing into `o`.
po::options_description visible_options(Options& o)
{
  po::options_description visible(
    "Usage: k_set_tilable INPUT -k K -o OUTPUT.ply [options]\n"
    "       k_set_tilable INPUT --max-deviation D [-k KMAX] -o OUTPUT.ply [options]\n"
    "       k_set_tilable INPUT --sweep KMIN:KMAX[:STEP] --curve CURVE.csv [--html CURVE.html] [options]\n"
    "Makes the quad mesh INPUT (OFF, OBJ or PLY; triangles allowed) tilable by K distinct panel shapes.\nOptions");
  visible.add_options()
    ("help,h", "print this help and exit")
    ("k,k", po::value<int>(&o.k), "number K of distinct tiles (S-quads); with --max-deviation, "
     "the largest K tried")
    ("max-deviation", po::value<double>(&o.max_deviation),
     "instead of K: the smallest K whose result is tilable, does not cross itself and is within "
     "this symmetric Hausdorff distance of the input, as a fraction of its bounding-box diagonal "
     "(0.01 = 1%)")
    ("sweep", po::value<std::string>(&o.sweep),
     "KMIN:KMAX[:STEP]: run every K of the range and write the curve (--curve), no mesh")
    ("curve", po::value<std::string>(&o.curve),
     "CSV of the K tried (--sweep or --max-deviation): K, DOF, congruence, Hausdorff distance, "
     "displacement, time, tilable, pairs of panels that cross, the smaller K refined (--sweep: a K "
     "whose own result ends farther than a smaller K's takes that one refined); scripts/plot_curve.sh "
     "draws it")
    ("output,o", po::value<std::string>(&o.output),
     "moved mesh: .ply (with face properties cluster, orientation, red/green/blue), "
     ".obj (a group and a material per tile, OUTPUT.mtl beside it) or .off (geometry only)")
    ("report", po::value<std::string>(&o.report), "JSON report of everything measured")
    ("catalog", po::value<std::string>(&o.catalog), "tile catalog, .csv or .json")
    ("components", po::value<std::string>(&o.components),
     "PLY picture of the edge-sharing components (paper Fig. 6)")
    ("html", po::value<std::string>(&o.html),
     "one self-contained HTML page to open in a browser, offline: the result in 3D by tile or by "
     "deviation with the input as a ghost (click a panel: its tile, mold, instances, deviation), the "
     "mold sheets, the summary and parameters, the K tried; with --sweep, the curve and its table")
    ("mold-sheets", po::value<std::string>(&o.mold_sheets),
     "directory (created if missing) for one SVG mold sheet per tile, tile_000.svg ...: the tile drawn "
     "in model units with a scale bar, corners t0..t3 numbered as the PLY's orientations number them, "
     "edge and diagonal lengths, corner angles, twist, instances")
    ("distance-weight", po::value<double>(&o.distance_weight)->default_value(o.distance_weight),
     "mu1, closeness to the input")
    ("fairness-weight", po::value<double>(&o.fairness_weight),
     "mu2: default solver, rigidity of the displacement (default 1e-6); paper-cg, the paper's "
     "fairness (default 1e-4)")
    ("tangential-weight", po::value<double>(&o.tangential_weight)->default_value(o.tangential_weight),
     "default solver: cost of sliding in the input surface relative to leaving it, in (0, 1]")
    ("optimized-candidates", po::value<int>(&o.optimized_candidates),
     "default solver: clusterings optimized fully, the closest result is kept; 0: none if a sweep is exact, "
     "else 1 (default: 2 + 10000 / faces, at most 12; 0 above 5000 faces)")
    ("improvement-rounds", po::value<int>(&o.improvement_rounds)->default_value(o.improvement_rounds),
     "default solver: rounds of split, merge and re-optimization, each kept only if better")
    ("candidates", po::value<int>(&o.candidates)->default_value(o.candidates),
     "candidate configurations kept while clustering")
    ("solver", po::value<std::string>(&o.solver)->default_value("gauss-newton"),
     "gauss-newton (exact, default) or paper-cg (the paper's conjugate gradient)")
    ("fixed-boundary", po::bool_switch(&o.fixed_boundary), "boundary vertices do not move")
    ("iterations", po::value<int>(&o.iterations), "maximum solver iterations")
    ("time-limit", po::value<double>(&o.time_limit),
     "seconds from the start after which no solver makes another step: the best result so far is "
     "kept (a grid's exact sweep at least); clustering and measurement are not interrupted, and the "
     "result then depends on the machine's speed")
    ("seed", po::value<unsigned int>(&o.seed)->default_value(o.seed), "random seed")
    ("threads", po::value<int>(&o.threads)->default_value(0), "threads (0: all cores)")
    ("mirror", po::bool_switch(&o.mirror),
     "a panel may be the mirror image of its mold (cut from the mirrored mold)")
    ("planar", po::bool_switch(&o.planar),
     "every panel planar as well as congruent (glass): its diagonals within 1e-6 of the mean edge "
     "of each other; default solver only")
    ("panel-tolerance", po::value<double>(&o.panel_tolerance),
     "T in model units: every panel within T of its mold (largest corner distance after the best rigid "
     "fit) instead of exactly congruent; the result is pulled back toward the input within T, panels that already "
     "fit one mold within T may share it unmoved, and with --max-deviation K is the smallest that meets "
     "both (default 0: exact, 1e-6 of the mean edge)")
    ("panel-tolerance-relative", po::value<double>(&o.panel_tolerance_relative),
     "the same T as a fraction of the input's mean edge length (1e-3: a millimetre on 1 m panels)")
    ("ascii", po::bool_switch(&o.ascii), "ASCII PLY instead of binary")
    ("quiet,q", po::bool_switch(&o.quiet), "no progress on stderr");
  return visible;
}

// What the command does (-k, --max-deviation or --sweep) and the files it writes, checked.
void check_mode(const po::variables_map& vm, Options& o)
{
  if(vm.count("k") && o.k < 1)
    throw Usage_error("-k must be at least 1, got " + std::to_string(o.k));
  if(vm.count("max-deviation") && !(o.max_deviation >= 0))
    throw Usage_error("--max-deviation must be >= 0 (a fraction of the bounding-box diagonal)");
  if(!o.sweep.empty())
  {
    o.sweep_k = parse_sweep(o.sweep);
    if(vm.count("k") || vm.count("max-deviation"))
      throw Usage_error("--sweep runs its own K: give neither -k nor --max-deviation");
    if(o.curve.empty())
      throw Usage_error("--sweep needs --curve CURVE.csv");
    if(!o.output.empty() || !o.report.empty() || !o.catalog.empty() || !o.components.empty() ||
       !o.mold_sheets.empty())
      throw Usage_error("--sweep writes the curve only (and --html its page): no -o, --report, --catalog, "
                        "--components or --mold-sheets");
  }
  else
  {
    if(!vm.count("k") && !vm.count("max-deviation"))
      throw Usage_error("give -k K, --max-deviation D or --sweep KMIN:KMAX");
    if(o.output.empty())
      throw Usage_error("the option '--output' is required but missing");
    if(!o.curve.empty() && !vm.count("max-deviation"))
      throw Usage_error("--curve needs --sweep or --max-deviation");
  }
  if(!o.curve.empty() && extension(o.curve) != "csv")
    throw Usage_error("the curve '" + o.curve + "' must end in .csv");
  if(!o.html.empty() && extension(o.html) != "html" && extension(o.html) != "htm")
    throw Usage_error("the HTML report '" + o.html + "' must end in .html or .htm");
}

// The files and values of a run that writes a mesh, checked.
void check_run_options(const po::variables_map& vm, const Options& o)
{
  const std::string out_ext = extension(o.output);
  if(out_ext != "ply" && out_ext != "off" && out_ext != "obj")
    throw Usage_error("the output '" + o.output + "' must end in .ply, .off or .obj");
  if(!o.catalog.empty() && extension(o.catalog) != "csv" && extension(o.catalog) != "json")
    throw Usage_error("the catalog '" + o.catalog + "' must end in .csv or .json");
  if(!o.report.empty() && extension(o.report) != "json")
    throw Usage_error("the report '" + o.report + "' must end in .json");
  if(!o.components.empty() && extension(o.components) != "ply")
    throw Usage_error("the components picture '" + o.components + "' must end in .ply");
  if(o.solver != "gauss-newton" && o.solver != "paper-cg")
    throw Usage_error("unknown solver '" + o.solver + "' (gauss-newton or paper-cg)");
  if(o.planar && o.solver != "gauss-newton")
    throw Usage_error("--planar needs the default solver (gauss-newton)");
  if(o.candidates < 1)
    throw Usage_error("--candidates must be at least 1");
  if(vm.count("iterations") && o.iterations < 0)
    throw Usage_error("--iterations must be >= 0");
  if(o.threads < 0)
    throw Usage_error("--threads must be >= 0");
  if(vm.count("time-limit") && !(o.time_limit >= 0))
    throw Usage_error("--time-limit must be >= 0");
  if(!(o.distance_weight > 0) || !(o.fairness_weight >= 0 || o.fairness_weight == -1))
    throw Usage_error("--distance-weight must be > 0 and --fairness-weight >= 0");
  if(!(o.tangential_weight > 0 && o.tangential_weight <= 1))
    throw Usage_error("--tangential-weight must be in (0, 1]");
  if((vm.count("optimized-candidates") && o.optimized_candidates < 0) || o.improvement_rounds < 0)
    throw Usage_error("--optimized-candidates and --improvement-rounds must be >= 0");
  check_panel_tolerance(vm, o);
}

Options parse(int argc, char** argv, bool& help)
{
  Options o;
  const po::options_description visible = visible_options(o);
  po::options_description hidden;
  hidden.add_options()("input", po::value<std::string>(&o.input)->required(), "input mesh");
  po::options_description all;
  all.add(visible).add(hidden);
  po::positional_options_description positional;
  positional.add("input", 1);

  po::variables_map vm;
  try
  {
    po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), vm);
    if(vm.count("help"))
    {
      help = true;
      std::cout << visible << "\n";
      return o;
    }
    po::notify(vm);
  }
  catch(const po::error& e)
  {
    throw Usage_error(e.what());
  }

  check_mode(vm, o);
  if(o.sweep.empty())
    check_run_options(vm, o);
  return o;
}

Mesh read_input(const std::string& path)
{
  Mesh mesh;
  try
  {
    // Counts checked against the file size, unused vertices kept.
    for(const std::string& w : TS::IO::read_panel_mesh(path, mesh).warnings)
      std::cerr << "[k_set_tilable] warning: " << path << ": " << w << "\n";
  }
  catch(const TS::Invalid_input& e)
  {
    throw Usage_error(e.what());
  }
  return mesh;
}

// Progress on stderr: one line per phase, one per solver iteration; stops
// the solvers once `clock` passes `time_limit` (none if negative).
struct Progress_visitor : TS::Default_visitor
{
  bool quiet = false;
  double time_limit = -1;
  const CGAL::Real_timer* clock = nullptr;
  bool stopped = false; // by the time limit, at least once
  bool iteration(int it, double congruence, double objective)
  {
    if(!quiet)
      std::cerr << "  iteration " << std::setw(3) << it << ": congruence error "
                << std::scientific << std::setprecision(2) << congruence << ", objective "
                << objective << std::defaultfloat << "\n";
    if(time_limit >= 0 && clock->time() > time_limit)
      stopped = true;
    return !stopped;
  }
  void phase(const char* name, double seconds)
  {
    if(!quiet)
      std::cerr << "[k_set_tilable] " << name << " done in " << std::fixed << std::setprecision(2)
                << seconds << " s" << std::defaultfloat << "\n";
  }
};

// Each output is written to a temporary file and renamed at the end, so a
// failure never leaves a partial file.
class Output_files
{
public:
  void add(const std::string& path, const std::function<bool(std::ostream&)>& write)
  {
    const std::string tmp = path + ".tmp";
    std::ofstream out(tmp, std::ios::binary);
    if(!out || !write(out) || !(out.flush()))
    {
      std::remove(tmp.c_str());
      discard();
      throw std::runtime_error("cannot write '" + path + "'");
    }
    m_pending.emplace_back(tmp, path);
  }
  void commit()
  {
    for(const auto& p : m_pending)
      if(std::rename(p.first.c_str(), p.second.c_str()) != 0)
        throw std::runtime_error("cannot create '" + p.second + "'");
    m_pending.clear();
  }
  void discard()
  {
    for(const auto& p : m_pending) std::remove(p.first.c_str());
    m_pending.clear();
  }
  ~Output_files() { discard(); }

private:
  std::vector<std::pair<std::string, std::string> > m_pending;
};

// Checks that a file can be created at `path` before the long computation.
void check_writable(const std::string& path)
{
  if(path.empty())
    return;
  const std::string probe = path + ".tmp";
  if(!std::ofstream(probe))
    throw Usage_error("cannot create '" + path + "' (missing directory or no permission)");
  std::remove(probe.c_str());
}

// Checks that the directory `path` exists and takes files, or can be created,
// before the long computation; it is created only when the sheets are written.
void check_directory(const std::string& path)
{
  if(path.empty())
    return;
  namespace fs = std::filesystem;
  std::error_code error;
  if(fs::exists(path, error))
  {
    if(!fs::is_directory(path, error))
      throw Usage_error("--mold-sheets '" + path + "' is not a directory");
    check_writable((fs::path(path) / "tile_000.svg").string());
    return;
  }
  if(!fs::create_directory(path, error))
    throw Usage_error("cannot create the directory '" + path + "' (missing parent directory or no permission)");
  fs::remove(path, error);
}

// The text of the file `name` of the three.js files fetched when the program
// was built (scripts/fetch_three.sh), or empty.
std::string three_js_file(const std::string& name)
{
#ifdef TILABLE_SURFACES_THREE_JS_DIR
  std::ifstream in(std::string(TILABLE_SURFACES_THREE_JS_DIR) + "/" + name, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return in ? text.str() : std::string();
#else
  (void)name;
  return std::string();
#endif
}

// The scripts the HTML report embeds; a clear error when this build has none.
TS::IO::HTML_viewer_scripts viewer_scripts()
{
  TS::IO::HTML_viewer_scripts scripts{three_js_file("three.module.min.js"), three_js_file("OrbitControls.js")};
  if(scripts.three_module.empty() || scripts.orbit_controls.empty())
    throw Usage_error("--html is not available in this build: three.js was not fetched from the npm registry when "
                      "k_set_tilable was built (build the target three_js with npm and the registry reachable, "
                      "then k_set_tilable again)");
  return scripts;
}

// The parameters of the run, for the reports.
nlohmann::json parameters_json(const Options& o, std::size_t optimized)
{
  const TS::Solver_type solver =
    o.solver == "paper-cg" ? TS::PAPER_CONJUGATE_GRADIENT : TS::CONSTRAINED_GAUSS_NEWTON;
  return {{"K", o.k > 0 ? nlohmann::json(o.k) : nlohmann::json(nullptr)},
          {"max_deviation", o.max_deviation >= 0 ? nlohmann::json(o.max_deviation) : nlohmann::json(nullptr)},
          {"sweep", o.sweep.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.sweep)},
          {"mirror", o.mirror},
          {"planar", o.planar},
          {"panel_tolerance", o.panel_tolerance},
          {"panel_tolerance_relative", o.panel_tolerance_relative > 0 ? nlohmann::json(o.panel_tolerance_relative)
                                                                      : nlohmann::json(nullptr)},
          {"distance_weight", o.distance_weight},
          {"fairness_weight", o.fairness_weight < 0 ? TS::default_fairness_weight(solver) : o.fairness_weight},
          {"tangential_weight", o.tangential_weight},
          {"optimized_candidates", optimized},
          {"improvement_rounds", o.improvement_rounds},
          {"candidates", o.candidates},
          {"solver", o.solver},
          {"fixed_boundary", o.fixed_boundary},
          {"iterations", o.iterations},
          {"time_limit", o.time_limit >= 0 ? nlohmann::json(o.time_limit) : nlohmann::json(nullptr)},
          {"seed", o.seed},
          {"threads", o.threads}};
}

// --sweep: the curve file, its HTML page if asked, and a table on stderr.
int write_curve(const Options& o, const std::vector<TS::Tile_count_trial>& trials, std::size_t optimized,
                const CGAL::Real_timer& timer)
{
  Output_files files;
  files.add(o.curve, [&](std::ostream& out) { return TS::IO::write_tile_count_curve_CSV(out, trials); });
  if(!o.html.empty())
    files.add(o.html, [&](std::ostream& out) {
      const nlohmann::json report = {{"input", {{"file", o.input}}},
                                     {"parameters", parameters_json(o, optimized)},
                                     {"tried_K", TS::IO::tile_count_trials_json(trials)}};
      return TS::IO::write_HTML_curve_report(out, trials, report);
    });
  files.commit();
  std::cerr << "[k_set_tilable]    K   DOF  congruence  Hausdorff  displacement  seconds\n";
  for(const TS::Tile_count_trial& t : trials)
    std::cerr << "[k_set_tilable] " << std::setw(4) << t.number_of_tiles << std::setw(6)
              << t.degree_of_flexibility << std::scientific << std::setprecision(2) << std::setw(12)
              << t.congruence_error << std::fixed << std::setw(10) << 100 * t.hausdorff_distance
              << "%" << std::scientific << std::setw(14) << t.max_displacement << std::fixed
              << std::setw(9) << t.seconds << (t.is_tilable ? "" : "  not tilable")
              << (t.refined_from > 0 ? "  refined from K = " + std::to_string(t.refined_from) : "") << "\n";
  std::cerr << "[k_set_tilable] curve written to " << o.curve << " in " << std::fixed
            << std::setprecision(2) << timer.time() << " s\n";
  return 0;
}

// The user's --optimized-candidates, or the package's default for `mesh`.
std::size_t optimized_candidates(const Options& o, const Mesh& mesh)
{
  return o.optimized_candidates >= 0 ? std::size_t(o.optimized_candidates)
                                     : TS::default_number_of_optimized_candidates(num_faces(mesh));
}

// The JSON report: what the library measured, and the input and parameters.
nlohmann::json report_json(const Options& o, const TS::K_set_tilable_result& result, const Mesh& input,
                           const TS::Mold_count_bounds& bounds, std::size_t optimized, bool time_limit_reached,
                           double seconds)
{
  nlohmann::json report = TS::IO::tilability_report_json(result);
  report["input"] = {{"file", o.input},
                     {"vertices", input.number_of_vertices()},
                     {"faces", input.number_of_faces()},
                     {"mold_count_bounds", {{"unstructured_molds", bounds.unstructured_molds},
                                            {"grid_patches", bounds.grid_patches},
                                            {"patch_sweep_molds", bounds.patch_sweep_molds}}}};
  report["parameters"] = parameters_json(o, optimized);
  report["time_limit_reached"] = time_limit_reached;
  report["time_seconds"]["total_with_io"] = seconds;
  return report;
}

// Says when K is below both mold counts of the input: unless its panels
// repeat, an exact result is then far from it, or is not found.
void warn_of_few_molds(const Options& o, const TS::Mold_count_bounds& bounds)
{
  if(o.quiet || !o.sweep.empty() || o.max_deviation >= 0 ||
     std::size_t(o.k) >= (std::min)(bounds.unstructured_molds, bounds.patch_sweep_molds))
    return;
  std::cerr << "[k_set_tilable] note: K = " << o.k << " is below the " << bounds.patch_sweep_molds
            << " molds of a sweep of each grid patch alone (" << bounds.grid_patches << " patches) and the "
            << bounds.unstructured_molds << " a clustering without structure needs (user manual, \"How many molds "
            << "a mesh needs\"): unless its panels repeat, an exact result is far from the input or is not "
               "found; --max-deviation D finds the smallest K within D\n";
}

// With a panel tolerance, the certificate: every panel within T of its mold,
// and the worst deviation, in model units.
void print_panel_tolerance(const TS::Tilability_measure& m)
{
  if(m.panel_tolerance <= 0)
    return;
  std::cerr << "[k_set_tilable] " << (m.within_panel_tolerance() ? "every panel within " : "NOT every panel within ")
            << std::defaultfloat << std::setprecision(4) << m.panel_tolerance
            << " of its mold (model units; " << m.panel_tolerance / m.mean_edge_length
            << " of the mean edge): the worst deviates " << m.worst_panel_deviation << "\n";
}

// Why the result is not tilable, and what may help: what was missed (exact
// congruence, or every panel within the panel tolerance) and how the solver ended.
void explain_not_tilable(const Options& o, const TS::K_set_tilable_result& result, bool stopped)
{
  const TS::Tilability_measure& m = result.optimization.measure;
  const bool tolerance = m.panel_tolerance > 0;
  std::cerr << "[k_set_tilable] not every panel fits its mold " << (m.requires_planar_tiles ? "and is planar " : "")
            << (tolerance ? "within the panel tolerance; see the report's panel_deviation\n"
                          : "within 1e-6 of the mean edge length; see the report's per-cluster congruence errors\n");
  if(result.optimization.stalled)
  {
    std::cerr << "[k_set_tilable] no ";
    if(tolerance)
      std::cerr << "solution within the panel tolerance " << std::defaultfloat << std::setprecision(4)
                << m.panel_tolerance << " near the input for this clustering: the solver stalled with a panel "
                << m.worst_panel_deviation << " (model units) from its mold";
    else
      std::cerr << "exact solution near the input for this clustering: the solver stalled at " << std::scientific
                << std::setprecision(2) << m.congruence_error << std::defaultfloat;
    std::cerr << " with iterations left, after " << result.clustering.number_of_edit_rounds
              << " rounds of split and merge (improvement and repair); more iterations would not help, a larger K may"
              << (o.max_deviation >= 0 ? "" : " (--max-deviation D searches the smallest K within D)") << "\n";
  }
  else if(!stopped)
    std::cerr << "[k_set_tilable] the solver used all its " << result.optimization.iterations
              << " iterations: more (--iterations N) may make it tilable\n";
}

// The mean edge length of `mesh`, the unit of --panel-tolerance-relative.
double mean_edge_length(const Mesh& mesh)
{
  double sum = 0;
  for(Mesh::Edge_index e : mesh.edges())
    sum += std::sqrt(CGAL::squared_distance(mesh.point(mesh.source(mesh.halfedge(e))),
                                            mesh.point(mesh.target(mesh.halfedge(e)))));
  return mesh.number_of_edges() > 0 ? sum / double(mesh.number_of_edges()) : 0.0;
}

int run_on(const Options& o, Mesh& mesh, const Mesh& input, const TS::IO::HTML_viewer_scripts& scripts,
           const CGAL::Real_timer& timer);

int run(const Options& o)
{
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> threads;
  if(o.threads > 0)
    threads.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism, o.threads));
#endif
  for(const std::string& path : {o.output, o.report, o.catalog, o.components, o.curve, o.html})
    check_writable(path);
  check_directory(o.mold_sheets);
  // The page of a sweep has no 3D view, and so no three.js.
  const TS::IO::HTML_viewer_scripts scripts =
    o.html.empty() || !o.sweep.empty() ? TS::IO::HTML_viewer_scripts() : viewer_scripts();

  CGAL::Real_timer timer;
  timer.start();
  Mesh mesh = read_input(o.input);
  const Mesh input = mesh;
  Options options = o;
  if(o.panel_tolerance_relative > 0)
    options.panel_tolerance = o.panel_tolerance_relative * mean_edge_length(mesh);
  return run_on(options, mesh, input, scripts, timer);
}

// The run on the mesh read, with the panel tolerance in model units.
int run_on(const Options& o, Mesh& mesh, const Mesh& input, const TS::IO::HTML_viewer_scripts& scripts,
           const CGAL::Real_timer& timer)
{
  Progress_visitor progress;
  progress.quiet = o.quiet;
  progress.time_limit = o.time_limit;
  progress.clock = &timer;
  progress.phase("reading", timer.time());
  if(!o.quiet)
    std::cerr << "[k_set_tilable] " << o.input << ": " << mesh.number_of_vertices() << " vertices, "
              << mesh.number_of_faces() << " faces, "
              << (!o.sweep.empty() ? "K = " + o.sweep
                  : o.max_deviation >= 0 ? "deviation budget " + std::to_string(o.max_deviation)
                                         : "K = " + std::to_string(o.k))
              << (o.panel_tolerance > 0 ? ", panel tolerance " + std::to_string(o.panel_tolerance) : "") << "\n";

  const TS::Mold_count_bounds bounds = TS::mold_count_bounds(mesh);
  warn_of_few_molds(o, bounds);

  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:ts_cluster", 0).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:ts_orientation", 0).first;
  auto fixed = mesh.add_property_map<Mesh::Vertex_index, bool>("v:ts_fixed", false).first;
  if(o.fixed_boundary)
    for(auto v : vertices(mesh)) fixed[v] = bool(CGAL::is_border(v, mesh));

  const TS::Solver_type solver =
    o.solver == "paper-cg" ? TS::PAPER_CONJUGATE_GRADIENT : TS::CONSTRAINED_GAUSS_NEWTON;
  auto np = TSP::face_cluster_map(cluster)
              .face_orientation_map(orientation)
              .vertex_is_constrained_map(fixed)
              .distance_weight(o.distance_weight)
              .fairness_weight(o.fairness_weight < 0 ? TS::default_fairness_weight(solver)
                                                     : o.fairness_weight)
              .tangential_weight(o.tangential_weight)
              .number_of_optimized_candidates(optimized_candidates(o, mesh))
              .number_of_improvement_rounds(o.improvement_rounds)
              .number_of_candidates(std::size_t(o.candidates))
              .solver(solver)
              .random_seed(o.seed)
              .orientation_policy(o.mirror ? TS::ALLOW_MIRRORED_PANELS : TS::PROPER_RIGID_MOTIONS)
              .planar_tiles(o.planar)
              .panel_tolerance(o.panel_tolerance)
              .number_of_iterations(o.iterations >= 0 ? o.iterations : TS::default_number_of_iterations(solver))
              .visitor(std::ref(progress));
  if(!o.sweep.empty())
    return write_curve(o, TS::k_set_tilable_curve<CGAL::Parallel_if_available_tag>(mesh, o.sweep_k, np),
                       optimized_candidates(o, mesh), timer);
  const int largest_k = o.k > 0 ? o.k : int(num_faces(mesh));
  TS::K_set_tilable_result result = o.max_deviation >= 0
    ? TS::make_k_set_tilable<CGAL::Parallel_if_available_tag>(mesh, np.max_deviation(o.max_deviation).number_of_tiles(largest_k))
    : TS::make_k_set_tilable<CGAL::Parallel_if_available_tag>(mesh, np.number_of_tiles(o.k));

  CGAL::Real_timer write_timer;
  write_timer.start();
  Output_files files;
  if(extension(o.output) == "ply")
    files.add(o.output, [&](std::ostream& out) {
      return TS::IO::write_tiled_PLY(out, mesh, TSP::face_cluster_map(cluster)
                                                  .face_orientation_map(orientation)
                                                  .use_binary_mode(!o.ascii));
    });
  else if(extension(o.output) == "obj")
  {
    // OUTPUT.obj with a group and a material per tile, and OUTPUT.mtl beside it.
    const std::filesystem::path mtl = std::filesystem::path(o.output).replace_extension(".mtl");
    files.add(o.output, [&](std::ostream& out) {
      return TS::IO::write_tiled_OBJ(out, mesh, mtl.filename().string(),
                                     TSP::face_cluster_map(cluster));
    });
    files.add(mtl.string(), [&](std::ostream& out) {
      return TS::IO::write_tiled_MTL(out, mesh, TSP::face_cluster_map(cluster));
    });
  }
  else
  {
    if(!o.quiet)
      std::cerr << "[k_set_tilable] note: off keeps the geometry only; use .ply for clusters, "
                   "orientations and colours, or .obj for clusters and colours\n";
    files.add(o.output, [&](std::ostream& out) {
      out << std::setprecision(17);
      return CGAL::IO::write_OFF(out, mesh);
    });
  }
  if(!o.catalog.empty())
    files.add(o.catalog, [&](std::ostream& out) {
      return extension(o.catalog) == "csv" ? TS::IO::write_tile_catalog_CSV(out, result.tiles)
                                           : TS::IO::write_tile_catalog_JSON(out, result.tiles);
    });
  if(!o.components.empty())
  {
    const TS::Edge_sharing_graph<Mesh> graph(mesh, result.optimization.measure.number_of_clusters,
                                             cluster, orientation);
    files.add(o.components, [&](std::ostream& out) {
      return TS::IO::write_edge_components_PLY(out, mesh, graph.edge_component_map(),
                                               TSP::use_binary_mode(!o.ascii));
    });
  }
  if(!o.curve.empty())
    files.add(o.curve, [&](std::ostream& out) { return TS::IO::write_tile_count_curve_CSV(out, result.trials); });
  const nlohmann::json report = o.report.empty() && o.html.empty() ? nlohmann::json()
    : report_json(o, result, input, bounds, optimized_candidates(o, mesh), progress.stopped, timer.time());
  if(!o.report.empty())
    files.add(o.report, [&](std::ostream& out) {
      out << std::setw(2) << report << "\n";
      return bool(out);
    });
  if(!o.html.empty())
    files.add(o.html, [&](std::ostream& out) {
      return TS::IO::write_HTML_report(out, mesh, input, result, report, scripts,
                                       TSP::face_cluster_map(cluster).face_orientation_map(orientation));
    });
  if(!o.mold_sheets.empty())
  {
    std::filesystem::create_directories(o.mold_sheets);
    for(std::size_t i = 0; i < result.tiles.size(); ++i)
      if(result.tiles[i].instance_count > 0)
        files.add((std::filesystem::path(o.mold_sheets) / TS::IO::mold_sheet_file_name(result.tiles[i])).string(),
                  [&](std::ostream& out) { return TS::IO::write_mold_sheet_SVG(out, result.tiles, i); });
  }
  files.commit();
  progress.phase("writing", write_timer.time());

  const TS::Tilability_measure& m = result.optimization.measure;
  std::cerr << "[k_set_tilable] K = " << m.number_of_clusters << ", DOF = " << m.degree_of_flexibility
            << ", congruence error " << std::scientific << std::setprecision(2) << m.congruence_error
            << ", Hausdorff distance to the input max " << m.hausdorff_distance << " mean "
            << m.mean_symmetric_distance << " (of the bbox diagonal; "
            << m.in_input_edge_lengths(m.hausdorff_distance) << " edge lengths), displacement max "
            << m.max_displacement << ", " << std::defaultfloat
            << std::fixed << std::setprecision(2) << timer.time() << " s\n";
  if(o.max_deviation >= 0)
  {
    std::cerr << "[k_set_tilable] K tried:";
    for(const TS::Tile_count_trial& t : result.trials)
    {
      std::cerr << " " << t.number_of_tiles << (t.meets(o.max_deviation) ? " (within," : " (missed,")
                << std::defaultfloat << std::setprecision(3) << " " << 100 * t.hausdorff_distance << "%";
      if(t.refined_from > 0)
        std::cerr << ", refined from K = " << t.refined_from;
      std::cerr << ")";
    }
    const bool met = !result.trials.empty() && std::any_of(result.trials.begin(), result.trials.end(),
      [&](const TS::Tile_count_trial& t) { return t.meets(o.max_deviation); });
    std::cerr << "\n[k_set_tilable] " << (met ? "smallest K within the budget: "
                                             : "WARNING: no K up to the largest tried meets the budget; result at K = ")
              << m.number_of_clusters << "\n";
  }
  if(m.number_of_distinct_molds < m.number_of_clusters)
    std::cerr << "[k_set_tilable] " << m.number_of_distinct_molds << " distinct molds: "
              << m.number_of_clusters - m.number_of_distinct_molds
              << " of the K S-quads came out congruent to another one (within 1e-6 of the mean edge length)\n";
  const std::size_t triangle_tiles = std::size_t(std::count_if(
    m.s_quads.begin(), m.s_quads.end(), [](const TS::Panel& s) { return s.is_triangle(); }));
  if(triangle_tiles > 0)
    std::cerr << "[k_set_tilable] " << m.number_of_clusters - triangle_tiles << " quad tiles and "
              << triangle_tiles << " triangle tiles\n";
  if(m.requires_planar_tiles)
    std::cerr << "[k_set_tilable] planar panels: the diagonals of every face are within "
              << std::scientific << std::setprecision(2) << m.planarity_error
              << " mean edge lengths of each other\n" << std::defaultfloat;
  if(m.allows_mirrored_panels)
  {
    std::size_t mirrored = 0;
    for(std::size_t c : m.cluster_mirrored_counts) mirrored += c;
    std::cerr << "[k_set_tilable] " << mirrored << " of " << num_faces(mesh)
              << " panels are cut from a mirrored mold\n";
  }
  std::cerr << "[k_set_tilable] " << (result.is_tilable() ? "tilable" : "NOT tilable") << ", "
            << m.self_intersecting_face_pairs << " crossing panel pairs, " << m.flattened_panels
            << " flattened panels, " << m.number_of_distinct_molds << " distinct molds for K = " << m.number_of_clusters
            << "\n";
  for(const std::string& warning : TS::buildability_warnings(m))
    std::cerr << "[k_set_tilable] WARNING: " << warning << "\n";
  print_panel_tolerance(m);
  if(!result.is_tilable())
    explain_not_tilable(o, result, progress.stopped);
  if(progress.stopped)
    std::cerr << "[k_set_tilable] the time limit (" << std::defaultfloat << std::setprecision(6) << o.time_limit
              << " s) ended the search: the result is the best found by then"
              << (result.is_tilable() ? "" : "; a longer --time-limit may make it tilable") << "\n";
  if(m.self_intersecting_face_pairs > 0)
    std::cerr << "[k_set_tilable] a larger K may untangle the crossing panels\n";
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  try
  {
    bool help = false;
    options = parse(argc, argv, help);
    if(help)
      return 0;
    return run(options);
  }
  catch(const Usage_error& e)
  {
    std::cerr << "k_set_tilable: error: " << e.what() << "\n";
    return 2;
  }
  catch(const TS::Invalid_input& e)
  {
    std::cerr << "k_set_tilable: error: " << options.input << ": " << e.what() << "\n";
    return 2;
  }
  catch(const std::exception& e)
  {
    std::cerr << "k_set_tilable: internal failure: " << e.what() << "\n";
    return 1;
  }
}
