// GLSL programs put together from one table of libraries. A line holding only "//UV::Name" stands
// for library Name; a library may hold such lines itself and may name libraries it needs first.
// Each library goes in once, where it is first asked for (its own needs before it); a later line for
// it is dropped. A line naming no library of the table becomes an #error, so the program fails to
// compile with the name in its log instead of silently missing code. VTK-free.
#ifndef uvShaderComposer_h
#define uvShaderComposer_h

#include <cstddef>
#include <set>
#include <string>
#include <vector>

namespace uv
{
struct ShaderLibrary
{
  std::string Name;                 ///< as its marker names it: "//UV::Name"
  const char* Source = nullptr;     ///< the GLSL text
  std::vector<std::string> Needs;   ///< libraries whose code it uses, put in before it
};

struct ComposedShader
{
  std::string Text;
  std::vector<std::string> Missing; ///< markers naming no library (each an #error in Text)
};

namespace detail
{
/// The library name of a marker line ("//UV::Name" alone, blanks around it allowed), or "".
inline std::string MarkerName(const std::string& line)
{
  const std::string prefix = "//UV::";
  const std::size_t begin = line.find_first_not_of(" \t\r");
  const std::size_t end = line.find_last_not_of(" \t\r");
  if (begin == std::string::npos || line.compare(begin, prefix.size(), prefix) != 0)
    return std::string();
  std::string name = line.substr(begin + prefix.size(), end + 1 - begin - prefix.size());
  for (const char c : name)
  {
    const bool word = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    if (!word)
      return std::string(); // a marker mentioned in a comment's sentence
  }
  return name;
}

class Composer
{
public:
  explicit Composer(const std::vector<ShaderLibrary>& libraries)
    : Libraries(libraries)
  {
  }

  void Append(const std::string& text)
  {
    std::size_t start = 0;
    while (start < text.size())
    {
      std::size_t end = text.find('\n', start);
      const bool lastLine = end == std::string::npos;
      end = lastLine ? text.size() : end;
      const std::string line = text.substr(start, end - start);
      const std::string name = MarkerName(line);
      if (name.empty())
        this->Result.Text += line + (lastLine ? "" : "\n");
      else
        this->Insert(name);
      start = end + 1;
    }
  }

  ComposedShader Result;

private:
  void Insert(const std::string& name)
  {
    if (!this->Inserted.insert(name).second)
      return; // already in, where it was first asked for
    const ShaderLibrary* library = nullptr;
    for (const ShaderLibrary& candidate : this->Libraries)
      library = candidate.Name == name ? &candidate : library;
    if (!library || !library->Source)
    {
      this->Result.Missing.push_back(name);
      this->Result.Text += "#error no shader library for the marker //UV::" + name + "\n";
      return;
    }
    for (const std::string& need : library->Needs)
      this->Insert(need);
    this->Append(library->Source);
    if (!this->Result.Text.empty() && this->Result.Text.back() != '\n')
      this->Result.Text += "\n";
  }

  const std::vector<ShaderLibrary>& Libraries;
  std::set<std::string> Inserted;
};
} // namespace detail

/// `source` with `defines` inserted after the line `versionMarker` (where VTK puts the #version; at
/// the start where there is none) and every marker line replaced as the header says.
inline ComposedShader ComposeShader(const std::string& source, const std::string& defines,
  const std::vector<ShaderLibrary>& libraries, const std::string& versionMarker = "//VTK::System::Dec")
{
  std::string text = source;
  const std::size_t at = text.find(versionMarker + "\n");
  text.insert(at == std::string::npos ? 0 : at + versionMarker.size() + 1, defines);
  detail::Composer composer(libraries);
  composer.Append(text);
  return composer.Result;
}
} // namespace uv

#endif
