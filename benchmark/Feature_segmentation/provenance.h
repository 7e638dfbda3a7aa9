// The provenance of a benchmark's CSV: NAME.provenance.txt beside NAME.csv, lines
// "key: value" (program, arguments, machine, date). The manual's figure tables are made
// from the CSVs of results/ (doc/Feature_segmentation/results_tables.py), and their
// captions name the machine and the date from this file.
#ifndef FS_BENCH_PROVENANCE_H
#define FS_BENCH_PROVENANCE_H

#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

namespace fs_bench {

// The CPU model as /proc/cpuinfo names it.
inline std::string cpu_name()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while(std::getline(cpuinfo, line))
    if(line.compare(0, 10, "model name") == 0)
    {
      const std::size_t colon = line.find(':');
      if(colon != std::string::npos && colon + 2 <= line.size())
        return line.substr(colon + 2);
    }
  return "unknown";
}

// The CPU model and the number of hardware threads.
inline std::string machine_name()
{
  const unsigned cores = std::thread::hardware_concurrency();
  return cpu_name() + ", " + std::to_string(cores) + (cores == 1 ? " core" : " cores");
}

// Today's date (UTC), YYYY-MM-DD.
inline std::string iso_date()
{
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[16];
  std::strftime(text, sizeof text, "%Y-%m-%d", &utc);
  return text;
}

// Writes CSV_PATH with its extension replaced by ".provenance.txt". Does nothing when
// CSV_PATH does not exist (a table the run skipped).
inline void write_provenance(const std::filesystem::path& csv_path, int argc, char** argv)
{
  if(!std::filesystem::exists(csv_path)) return;
  std::filesystem::path path = csv_path;
  path.replace_extension(".provenance.txt");
  std::ofstream out(path);
  out << "program: " << std::filesystem::path(argv[0]).filename().string() << "\narguments:";
  for(int i = 1; i < argc; ++i) out << ' ' << argv[i];
  out << "\nmachine: " << machine_name() << "\ndate: " << iso_date() << "\n";
}

} // namespace fs_bench

#endif // FS_BENCH_PROVENANCE_H
