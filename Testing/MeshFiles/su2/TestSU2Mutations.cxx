// A seeded run of mutated SU2 files: lines deleted, duplicated, swapped or inserted, the file
// cut, tokens replaced by random, huge, negative, non-finite or garbage values, bytes flipped.
// Each mutant either reads as a valid mesh (which then writes back and reads back the same) or
// is a FileError; nothing else (no other exception, crash, hang or huge allocation).
#include "SU2TestFiles.h"

#include <random>
#include <vector>

using namespace su2test;

namespace
{
/// Makes mutants of one file with a fixed seed.
class Mutator
{
public:
  explicit Mutator(std::uint64_t seed)
    : Random(seed)
  {
  }

  /// `text` with one to three random mutations.
  std::string Mutate(std::string text)
  {
    const int count = this->Uniform(1, 3);
    for (int k = 0; k < count && !text.empty(); ++k)
    {
      text = this->MutateOnce(text);
    }
    return text;
  }

private:
  int Uniform(int low, int high)
  {
    return std::uniform_int_distribution<int>(low, high)(this->Random);
  }
  std::size_t Below(std::size_t size)
  {
    return std::uniform_int_distribution<std::size_t>(0, size - 1)(this->Random);
  }

  /// A replacement token: a small or random number, a huge or negative one, non-finite, garbage.
  std::string Token()
  {
    static const char* const odd[] = { "999999999999", "99999999999999999999", "-1", "-0", "nan",
      "inf", "-inf", "1e999", "1e-400", "garbage", "1.5abc", "3x", "+", "-", "0x10", "",
      "NPOIN=", "NELEM= 999999999999", "MARKER_TAG=", "=", "%", "2", "3", "5", "9", "10", "12",
      "13", "14" };
    switch (this->Uniform(0, 2))
    {
      case 0:
        return std::to_string(this->Uniform(-3, 40));
      case 1:
        return std::to_string(std::uniform_real_distribution<double>(-10, 10)(this->Random));
      default:
        return odd[this->Below(sizeof(odd) / sizeof(odd[0]))];
    }
  }

  /// Where each line starts (and the end of the text).
  static std::vector<std::size_t> LineStarts(const std::string& text)
  {
    std::vector<std::size_t> starts{ 0 };
    for (std::size_t k = 0; k < text.size(); ++k)
    {
      if (text[k] == '\n' && k + 1 < text.size())
      {
        starts.push_back(k + 1);
      }
    }
    starts.push_back(text.size());
    return starts;
  }

  std::string MutateOnce(const std::string& text)
  {
    const std::vector<std::size_t> starts = LineStarts(text);
    const std::size_t line = this->Below(starts.size() - 1);
    const std::size_t begin = starts[line], end = starts[line + 1];
    const std::string lineText = text.substr(begin, end - begin);
    switch (this->Uniform(0, 6))
    {
      case 0: // delete a line
        return text.substr(0, begin) + text.substr(end);
      case 1: // duplicate a line
        return text.substr(0, end) + lineText + text.substr(end);
      case 2: // cut the file
        return text.substr(0, this->Below(text.size() + 1));
      case 3: // swap two lines
      {
        const std::size_t other = this->Below(starts.size() - 1);
        if (other <= line)
        {
          return text;
        }
        return text.substr(0, begin) +
          text.substr(starts[other], starts[other + 1] - starts[other]) +
          text.substr(end, starts[other] - end) + lineText + text.substr(starts[other + 1]);
      }
      case 4: // flip a bit of a byte
      {
        std::string flipped = text;
        flipped[this->Below(text.size())] ^= static_cast<char>(1 << this->Uniform(0, 7));
        return flipped;
      }
      case 5: // insert a line
        return text.substr(0, begin) + this->Token() + " " + this->Token() + "\n" +
          text.substr(begin);
      default: // replace a token of the line
        return text.substr(0, begin) + this->ReplaceToken(lineText) + text.substr(end);
    }
  }

  std::string ReplaceToken(const std::string& line)
  {
    std::vector<std::pair<std::size_t, std::size_t>> tokens;
    for (std::size_t k = 0; k < line.size();)
    {
      const std::size_t begin = line.find_first_not_of(" \t\r\n=", k);
      if (begin == std::string::npos)
      {
        break;
      }
      const std::size_t end = std::min(line.find_first_of(" \t\r\n=", begin), line.size());
      tokens.emplace_back(begin, end);
      k = end;
    }
    if (tokens.empty())
    {
      return line;
    }
    const auto& token = tokens[this->Below(tokens.size())];
    return line.substr(0, token.first) + this->Token() + line.substr(token.second);
  }

  std::mt19937_64 Random;
};

/// Runs `count` mutants of `text`; counts the valid ones and the errors.
void RunMutants(const std::string& text, std::uint64_t seed, int count)
{
  TemporaryFolder folder;
  const std::string file = folder.File("mutant.su2"), back = folder.File("back.su2");
  Mutator mutator(seed);
  int valid = 0, errors = 0;
  for (int k = 0; k < count; ++k)
  {
    const std::string mutant = mutator.Mutate(text);
    WriteText(file, mutant);
    try
    {
      const mf::NamedMesh mesh = mf::ReadSU2(file);
      mf::ValidateNamedMesh(mesh, file);
      mf::WriteSU2WithPoints(file, back, mesh.Points.data(), mesh.NumberOfNodes());
      const mf::NamedMesh again = mf::ReadSU2(back);
      ASSERT_TRUE(SameBits(again.Points, mesh.Points)) << mutant;
      ASSERT_EQ(again.Volume.Connectivity, mesh.Volume.Connectivity) << mutant;
      ++valid;
    }
    catch (const mf::FileError& e)
    {
      ASSERT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
      ++errors;
    }
    catch (const std::exception& e)
    {
      FAIL() << "mutant " << k << " threw " << e.what() << " (not a FileError):\n" << mutant;
    }
  }
  EXPECT_GT(valid, count / 50) << "too few mutants read: the run proves little";
  EXPECT_GT(errors, count / 2);
  std::cout << count << " mutants: " << valid << " valid, " << errors << " FileErrors\n";
}
} // namespace

TEST(SU2Mutations, Hand2D)
{
  RunMutants(Hand2D, 20240601, 1500);
}

TEST(SU2Mutations, Hand3DWithCRLF)
{
  RunMutants(WithCRLF(Hand3D), 20240602, 1500);
}

TEST(SU2Mutations, GmshCircleInSquare)
{
  RunMutants(ReadText(std::string(DGMF_SU2_TEST_DATA) + "/circle_in_square.su2"), 20240603, 1000);
}
