#pragma once

#include <string>
#include <vector>

// Line-oriented helpers shared by the orientation readers. Every reader
// reports bad input as "FILE:LINE: what is wrong", so lines keep their
// 1-based numbers from the file.
namespace roofsweep::orientation {

struct TextLine {
  int number = 0;  // 1-based line number in the file
  std::string text;
};

// All lines of a text file (CR stripped, UTF-8 BOM removed). Throws
// roofsweep::Error "PATH: cannot open ..." when the file is unreadable.
std::vector<TextLine> ReadTextLines(const std::string& path);
std::string ReadTextFile(const std::string& path);

std::string Trim(const std::string& s);
std::string Lower(std::string s);
bool StartsWith(const std::string& s, const std::string& prefix);
bool EndsWith(const std::string& s, const std::string& suffix);

// Splits on runs of spaces/tabs; '...' or "..." quoted fields may hold
// blanks (orthority writes names and camera ids that way) and lose quotes.
std::vector<std::string> SplitWhitespace(const std::string& line);
// Splits on one delimiter character, honouring quotes; fields are trimmed.
std::vector<std::string> SplitDelimited(const std::string& line, char delimiter);

// A finite number, or roofsweep::Error "FILE:LINE: WHAT: 'TOKEN' is not a
// number" (NaN and infinities are refused too).
double ParseNumber(const std::string& token, const std::string& file, int line,
                   const std::string& what);
int ParseInt(const std::string& token, const std::string& file, int line, const std::string& what);

// Numbers of a whitespace separated line, which must hold exactly `count`.
std::vector<double> ParseNumbers(const TextLine& line, const std::string& file, size_t count,
                                 const std::string& what);

}  // namespace roofsweep::orientation
