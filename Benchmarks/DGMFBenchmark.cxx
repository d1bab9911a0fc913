/**
 * dgmf-benchmark: the paper's Table 3 on this machine.
 *
 *   dgmf-benchmark [--sizes 0,1,2,3] [--methods dgm,dgmf,dgrbf,idw] [--threads 1,2]
 *                  [--repeats N] [--idw-max-size K] [--numberings layered,hilbert,random]
 *                  [--inputs grid,multiblock] [--quality 0] [--csv FILE]
 *                  [--frames N [--frames-csv FILE]]
 *                  [--command dgmf-deform [--command-csv FILE]]
 *
 * For each of the paper's mesh sizes (procedural layered hexahedral meshes, see LayeredMesh.h;
 * their generation is not timed), each method and each thread count: the first deformation
 * (graph, location and mapping, from an empty cache) and a repeated deformation with a new motion
 * (cache reused), through vtkDGMFDeformFilter with the quality metric off; then the quality
 * metric: the filter's own on new motions (quality_s; the hexahedra's original half cached) and a
 * new vtkSizeSkewQualityFilter's (quality_first_s). The cache is measured with the quality on.
 * Times are medians over the repeats. Writes one CSV row per configuration.
 *
 * --numberings: the node numberings of each mesh (Renumbering.h): the generator's layer by layer
 * (default), a Hilbert curve's (a renumbered unstructured mesh), a random permutation.
 * --inputs grid,multiblock: the mesh as one grid with its marker (default), and as a CFD reader's
 * multiblock (NamedBlocks.h: the volume and named patches, the body moving by name; layered
 * numbering only; the quality is not timed again).
 * --quality 0 (or off): the quality metric is not timed (its columns are empty).
 * --frames N: also a periodic motion of N frames (PeriodicMotion.h), DGMF on the grid, written to
 * --frames-csv FILE (default motion.csv): the first frame (the graph) and the frames per second.
 * --mesh FILE.vtu [--mesh-marker NAME] [--mesh-csv FILE]: instead, DGMF on that mesh (its marker
 * array, default BoundaryMarker): the first run's phases, a repeated run, the quality (mesh.csv).
 * --command PATH: also runs the command PATH (dgmf-deform) on the mesh written as a .vtu, with
 * each thread count, and writes its wall time and the read, filter and write times it prints,
 * beside the first deformation, to --command-csv FILE (default command.csv).
 */
#include "FirstAndRepeated.h"
#include "LayeredMesh.h"
#include "MeshFileCase.h"
#include "NamedBlocks.h"
#include "PeriodicMotion.h"
#include "Renumbering.h"
#include "WholeCommand.h"

#include "vtkDGMFDeformFilter.h"
#include "vtkSizeSkewQualityFilter.h"

#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkUnstructuredGrid.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

std::vector<std::string> Split(const std::string& list)
{
  std::vector<std::string> items;
  std::stringstream stream(list);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    items.push_back(item);
  }
  return items;
}

double PeakResidentMegabytes()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

struct Result
{
  double Graph = 0, Location = 0, Mapping = 0, First = 0, Repeated = 0, Quality = 0;
  double QualityWithFacesFirst = 0, QualityWithFaces = 0; // SizeSkew and non-orthogonality
  double QualityFirst = 0; // a new vtkSizeSkewQualityFilter (Quality: the filter's, repeated)
  double CacheBytesPerNode = 0;
};

const char* const Usage =
  "usage: dgmf-benchmark [--sizes 0,1,2,3] [--methods dgm,dgmf,dgrbf,idw] [--threads 1,2]\n"
  "         [--repeats N] [--idw-max-size K] [--numberings layered,hilbert,random]\n"
  "         [--inputs grid,multiblock] [--quality 0] [--csv FILE]\n"
  "         [--frames N [--frames-csv FILE]] [--command dgmf-deform [--command-csv FILE]]\n"
  "         [--mesh FILE.vtu [--mesh-marker NAME] [--mesh-csv FILE]]\n"
  "Times the paper's Table 3 on this machine (see the top of Benchmarks/DGMFBenchmark.cxx);\n"
  "writes benchmark.csv (or --csv FILE) in the current directory.\n";
} // namespace

int main(int argc, char* argv[])
{
  std::vector<std::string> sizes = { "0", "1", "2", "3" };
  std::vector<std::string> methods = { "dgm", "dgmf", "dgrbf", "idw" };
  std::vector<std::string> threads = { "1", "2" };
  std::vector<std::string> numberings = { "layered" };
  std::vector<std::string> inputs = { "grid" };
  std::string command;     // dgmf-deform, for the whole-command figure
  bool timeQuality = true; // --quality 0: the deformation only
  int frames = 0;          // --frames N: a periodic motion of N frames (issue 19)
  std::string meshFile;    // --mesh FILE.vtu: a mesh of the user's (issue 18)
  std::string meshMarker = "BoundaryMarker";
  std::string meshCsvPath = "mesh.csv";
  std::string framesCsvPath = "motion.csv";
  std::string commandCsvPath = "command.csv";
  int repeats = 3;
  int idwMaxSize = 1;
  std::string csvPath = "benchmark.csv";
  // Options come in pairs; a lone --help (or any odd option) must not start a run, which takes
  // minutes and overwrites benchmark.csv.
  for (int i = 1; i < argc; ++i)
  {
    const std::string option = argv[i];
    if (option == "--help" || option == "-h")
    {
      std::cout << Usage;
      return 0;
    }
  }
  if (argc % 2 == 0)
  {
    std::cerr << "dgmf-benchmark: option " << argv[argc - 1] << " has no value\n" << Usage;
    return 2;
  }
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    const std::string value = argv[i + 1];
    if (option == "--sizes")
      sizes = Split(value);
    else if (option == "--methods")
      methods = Split(value);
    else if (option == "--threads")
      threads = Split(value);
    else if (option == "--repeats")
      repeats = std::max(1, std::atoi(value.c_str()));
    else if (option == "--idw-max-size")
      idwMaxSize = std::atoi(value.c_str());
    else if (option == "--numberings")
      numberings = Split(value);
    else if (option == "--inputs")
      inputs = Split(value);
    else if (option == "--command")
      command = value;
    else if (option == "--quality")
      timeQuality = value != "0" && value != "off";
    else if (option == "--frames")
      frames = std::max(0, std::atoi(value.c_str()));
    else if (option == "--mesh")
      meshFile = value;
    else if (option == "--mesh-marker")
      meshMarker = value;
    else if (option == "--mesh-csv")
      meshCsvPath = value;
    else if (option == "--frames-csv")
      framesCsvPath = value;
    else if (option == "--command-csv")
      commandCsvPath = value;
    else if (option == "--csv")
      csvPath = value;
    else
    {
      std::cerr << "dgmf-benchmark: unknown option " << option << "\n";
      return 2;
    }
  }

  std::ofstream csv(csvPath);
  csv << "nodes,boundary_nodes,numbering,method,threads,graph_s,location_s,mapping_s,first_s,"
         "repeated_s,"
         "quality_s,cache_bytes_per_node,peak_rss_mb,quality_nonorth_first_s,quality_nonorth_s,"
         "input,quality_first_s\n";
  if (!meshFile.empty())
  {
    // A mesh of the user's instead of the procedural ones: DGMF's phases on it.
    std::ofstream meshCsv(meshCsvPath);
    meshCsv << "mesh,nodes,cells,threads,first_s,graph_s,location_s,mapping_s,overhead_s,"
               "repeated_s,quality_s\n";
    for (const std::string& threadName : threads)
    {
      const int threadCount = std::atoi(threadName.c_str());
      dgmf_bench::MeshFileTimes t;
      try
      {
        t = dgmf_bench::TimeMeshFile(meshFile, meshMarker, threadCount, repeats);
      }
      catch (const std::exception& e)
      {
        std::cerr << "dgmf-benchmark: " << e.what() << "\n";
        return 1;
      }
      meshCsv << std::filesystem::path(meshFile).filename().string() << "," << t.Nodes << ","
              << t.Cells << "," << threadCount << "," << t.First << "," << t.Graph << ","
              << t.Location << "," << t.Mapping << "," << t.Overhead << "," << t.Repeated << ","
              << t.Quality << "\n";
      std::cerr << std::fixed << std::setprecision(3) << meshFile << ", " << threadCount
                << " thread(s): first " << t.First << " s (graph " << t.Graph << ", location "
                << t.Location << ", mapping " << t.Mapping << ", the rest " << t.Overhead
                << "), repeated " << t.Repeated << " s, quality " << t.Quality << " s\n";
    }
    return 0;
  }
  std::ofstream framesCsv;
  if (frames > 1)
  {
    framesCsv.open(framesCsvPath);
    framesCsv << "nodes,threads,frames,first_frame_s,graph_s,other_frames_s,frames_per_second,"
                 "cycle_frames_per_second\n";
  }
  std::ofstream commandCsv;
  if (!command.empty())
  {
    commandCsv.open(commandCsvPath);
    commandCsv << "nodes,numbering,threads,first_s,wall_s,read_s,filter_s,write_s\n";
  }
  for (const std::string& sizeName : sizes)
  {
    const int sizeIndex = std::atoi(sizeName.c_str());
    const dgmf_bench::LayeredMeshSize size = dgmf_bench::PaperSize(sizeIndex);
    for (const std::string& numbering : numberings)
    {
      const Clock::time_point made = Clock::now();
      vtkSmartPointer<vtkUnstructuredGrid> mesh = dgmf_bench::MakeLayeredMesh(size);
      try
      {
        dgmf_bench::Renumber(mesh, dgmf_bench::NumberingFromName(numbering));
      }
      catch (const std::invalid_argument& e)
      {
        std::cerr << "dgmf-benchmark: " << e.what() << "\n";
        return 2;
      }
      std::cerr << "mesh " << size.Name << ", " << numbering
                << " numbering: " << mesh->GetNumberOfPoints() << " nodes, " << size.BoundaryNodes()
                << " boundary nodes, " << mesh->GetNumberOfCells() << " hexahedra (generated in "
                << Seconds(made) << " s)\n";
      vtkSmartPointer<vtkMultiBlockDataSet> blocks;
      std::map<int, double> dgmfFirst; // the first deformation by thread count
      for (const std::string& input : inputs)
      {
        if (input == "multiblock" && numbering == "layered")
        {
          blocks = dgmf_bench::MakeNamedBlocks(mesh, size);
        }
        else if (input != "grid")
        {
          std::cerr << "dgmf-benchmark: input " << input
                    << " unknown (grid, or multiblock with the layered numbering)\n";
          return 2;
        }
      }
      for (const std::string& input : inputs)
        for (const std::string& methodName : methods)
        {
          const bool multiblock = input == "multiblock";
          const int method = vtkDGMFDeformFilter::GetMethodFromName(methodName.c_str());
          if (method < 0)
          {
            std::cerr << "dgmf-benchmark: unknown method " << methodName << "\n";
            return 2;
          }
          if (method == vtkDGMFDeformFilter::IDW && sizeIndex > idwMaxSize)
          {
            continue; // O(N Nb): hours on the large meshes
          }
          const int methodRepeats = method == vtkDGMFDeformFilter::IDW ? 1 : repeats;
          for (const std::string& threadName : threads)
          {
            const int threadCount = std::atoi(threadName.c_str());
            Result result;
            vtkNew<vtkDGMFDeformFilter> filter;
            if (multiblock)
            {
              filter->SetInputData(blocks);
              filter->AddMovingBoundary("body"); // the farfield: the mesh's own boundary, static
            }
            else
            {
              filter->SetInputData(mesh);
              filter->SetBoundaryMarkerArrayName("BoundaryMarker");
            }
            filter->SetMethod(method);
            filter->SetNumberOfThreads(threadCount);
            filter->ComputeQualityOff();
            filter->SetTranslation(0.1, 0.0, 0.0);
            const dgmf_bench::FirstAndRepeated timed =
              dgmf_bench::TimeFirstAndRepeated(filter, methodRepeats);
            if (!timed.GraphAlwaysReused && method != vtkDGMFDeformFilter::IDW)
            {
              std::cerr << "dgmf-benchmark: the cache was not reused\n";
              return 1;
            }
            result.Graph = timed.Graph;
            result.Location = timed.Location;
            result.Mapping = timed.Mapping;
            result.First = timed.First;
            result.Repeated = timed.Repeated;
            result.CacheBytesPerNode =
              static_cast<double>(filter->GetCacheMemorySize()) / mesh->GetNumberOfPoints();
            if (methodName == "dgmf" && !multiblock)
            {
              dgmfFirst[threadCount] = result.First; // beside the whole command's time
            }
            if (methodName == "dgmf" && !multiblock && frames > 1)
            {
              const dgmf_bench::FrameRate rate =
                dgmf_bench::TimePeriodicMotion(mesh, threadCount, frames);
              framesCsv << mesh->GetNumberOfPoints() << "," << threadCount << "," << frames << ","
                        << rate.FirstFrame << "," << rate.Graph << "," << rate.OtherFrames << ","
                        << rate.FramesPerSecond << "," << rate.CycleFramesPerSecond << "\n";
              framesCsv.flush();
              std::cerr << std::fixed << std::setprecision(3) << "  dgmf, " << threadCount
                        << " thread(s), periodic motion: " << frames << " frames, the first "
                        << rate.FirstFrame << " s (graph " << rate.Graph << " s), then "
                        << std::setprecision(1) << rate.FramesPerSecond
                        << " frames/s (the whole cycle " << rate.CycleFramesPerSecond
                        << " frames/s)\n";
            }
            if (multiblock || !timeQuality) // the multiblock's quality is the grid's
            {
              csv << mesh->GetNumberOfPoints() << "," << size.BoundaryNodes() << "," << numbering
                  << "," << methodName << "," << threadCount << "," << result.Graph << ","
                  << result.Location << "," << result.Mapping << "," << result.First << ","
                  << result.Repeated << ",," << result.CacheBytesPerNode << ","
                  << PeakResidentMegabytes() << ",,," << input << ",\n";
              csv.flush();
              std::cerr << std::fixed << std::setprecision(3) << "  " << methodName << ", "
                        << threadCount << " thread(s), " << input << ": first " << result.First
                        << " s (graph " << result.Graph << ", location " << result.Location
                        << ", mapping " << result.Mapping << "), repeated " << result.Repeated
                        << " s, cache " << std::setprecision(1) << result.CacheBytesPerNode
                        << " B/node\n";
              continue;
            }

            // The quality metric alone, on the last output, by a new vtkSizeSkewQualityFilter
            // (nothing cached).
            vtkNew<vtkSizeSkewQualityFilter> quality;
            quality->SetInputData(filter->GetOutput());
            quality->SetReferenceData(mesh);
            quality->SetNumberOfThreads(threadCount);
            const Clock::time_point qualityStart = Clock::now();
            quality->Update();
            result.QualityFirst = Seconds(qualityStart);
            // The quality as the filter computes it for a new motion of the same mesh, the
            // hexahedra's original half kept from its first run with the quality on; the cache
            // is then measured with it (the quality is on by default).
            filter->ComputeQualityOn();
            filter->SetRotationAngles(5.0, 10.0, 25.0);
            filter->Update();
            std::vector<double> qualities;
            for (int r = 0; r < methodRepeats; ++r)
            {
              filter->SetRotationAngles(5.0, 10.0, 26.0 + r);
              filter->Update();
              qualities.push_back(filter->GetLastQualitySeconds());
            }
            result.Quality = dgmf_bench::Median(qualities);
            result.CacheBytesPerNode =
              static_cast<double>(filter->GetCacheMemorySize()) / mesh->GetNumberOfPoints();
            // With the face non-orthogonality: the first run finds the internal faces, the second
            // reuses them (a new motion of the same mesh).
            vtkNew<vtkSizeSkewQualityFilter> withFaces;
            withFaces->SetInputData(filter->GetOutput());
            withFaces->SetReferenceData(mesh);
            withFaces->SetNumberOfThreads(threadCount);
            withFaces->ComputeNonOrthogonalityOn();
            Clock::time_point facesStart = Clock::now();
            withFaces->Update();
            result.QualityWithFacesFirst = Seconds(facesStart);
            withFaces->Modified();
            facesStart = Clock::now();
            withFaces->Update();
            result.QualityWithFaces = Seconds(facesStart);

            csv << mesh->GetNumberOfPoints() << "," << size.BoundaryNodes() << "," << numbering
                << "," << methodName << "," << threadCount << "," << result.Graph << ","
                << result.Location << "," << result.Mapping << "," << result.First << ","
                << result.Repeated << "," << result.Quality << "," << result.CacheBytesPerNode
                << "," << PeakResidentMegabytes() << "," << result.QualityWithFacesFirst << ","
                << result.QualityWithFaces << "," << input << "," << result.QualityFirst << "\n";
            csv.flush();
            std::cerr << std::fixed << std::setprecision(3) << "  " << methodName << ", "
                      << threadCount << " thread(s): first " << result.First << " s (graph "
                      << result.Graph << ", location " << result.Location << ", mapping "
                      << result.Mapping << "), repeated " << result.Repeated << " s, quality "
                      << result.Quality << " s on a new motion (" << result.QualityFirst
                      << " s by a new quality filter; with non-orthogonality "
                      << result.QualityWithFacesFirst << " s first, " << result.QualityWithFaces
                      << " s repeated), cache " << std::setprecision(1) << result.CacheBytesPerNode
                      << " B/node\n";
          }
        }
      // The whole command on the same mesh, as a .vtu (the grid input; DGMF, the default).
      if (!command.empty())
      {
        const std::filesystem::path work =
          std::filesystem::temp_directory_path() / "dgmf-benchmark-command";
        std::filesystem::create_directories(work);
        for (const std::string& threadName : threads)
        {
          const int threadCount = std::atoi(threadName.c_str());
          dgmf_bench::CommandTimes times;
          try
          {
            times =
              dgmf_bench::TimeWholeCommand(mesh, command, work.string(), threadCount, repeats);
          }
          catch (const std::exception& e)
          {
            std::cerr << "dgmf-benchmark: " << e.what() << "\n";
            return 1;
          }
          const double first = dgmfFirst.count(threadCount) ? dgmfFirst[threadCount] : 0.0;
          commandCsv << mesh->GetNumberOfPoints() << "," << numbering << "," << threadCount << ","
                     << first << "," << times.Wall << "," << times.Read << "," << times.Filter
                     << "," << times.Write << "\n";
          commandCsv.flush();
          std::cerr << std::fixed << std::setprecision(3) << "  dgmf-deform, " << threadCount
                    << " thread(s): " << times.Wall << " s in all (read " << times.Read
                    << ", filter " << times.Filter << ", write " << times.Write << ")\n";
        }
        std::filesystem::remove_all(work);
      }
    }
  }
  return 0;
}
