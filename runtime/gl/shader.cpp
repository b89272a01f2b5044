// The shader library: turns a Variant (stage files + feature #defines) into a linked GL program,
// compiling each variant once and remembering which ones a run needed. Each stage is assembled as
// `#version 450 core`, the sorted #defines, then the stage file with its `#include`s expanded from
// the embedded table; `#line` directives tag every file so driver errors map back to
// shaders/<file>: line N.
//
// Trap (Mesa 22.3 at least): the source-string number in `#line L S` is not
// reliable. Mesa's preprocessor reports it, but its compiler reports most errors with string 0
// (its parser resets the location's source). So every file also gets its own block of line
// numbers: file S is numbered from S * kLinesPerFile + 1, and the line number alone says which
// file an error is in, whatever string number the driver printed.
#include "gl/shader.h"

#include <GL/glcorearb.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <regex>
#include <set>
#include <string_view>

#include "gl/context.h"

namespace bake::gl {
namespace {

// Line-number block per source string (see the top of the file); files must be shorter.
constexpr int kLinesPerFile = 100000;

// ---------------------------------------------------------------------------------------------
// Small text helpers

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

std::vector<std::string_view> splitLines(std::string_view text) {
  std::vector<std::string_view> lines;
  while (!text.empty()) {
    const auto end = text.find('\n');
    lines.push_back(text.substr(0, end));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return lines;
}

bool isIdentifier(std::string_view name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

std::string shadersPath(const std::string& path) { return "shaders/" + path; }
std::string lineElement(int line) { return "line " + std::to_string(line); }

// ---------------------------------------------------------------------------------------------
// Defines

// A define split into name and value ("FIELD_COUNT 2" -> {"FIELD_COUNT", "2"}).
struct Define {
  std::string name, value;
};

Define splitDefine(std::string_view text) {
  text = trim(text);
  const auto space = text.find_first_of(" \t");
  if (space == std::string_view::npos) return {std::string(text), ""};
  return {std::string(text.substr(0, space)), std::string(trim(text.substr(space)))};
}

// "NAME" or "NAME VALUE", whitespace normalised, sorted and without repeats: the one spelling used
// both in keys and in the generated #define lines, so equal variants always share one program.
std::vector<std::string> canonicalDefines(const std::vector<std::string>& defines) {
  std::set<std::string> sorted;
  for (const std::string& text : defines) {
    const Define define = splitDefine(text);
    sorted.insert(define.value.empty() ? define.name : define.name + " " + define.value);
  }
  return {sorted.begin(), sorted.end()};
}

// A define must be one identifier and a one-line value, and each name may have only one value;
// anything else would inject text into the preamble or make the key ambiguous.
Status checkDefines(const std::vector<std::string>& canonical, const std::string& key) {
  std::set<std::string> names;
  for (const std::string& text : canonical) {
    const Define define = splitDefine(text);
    if (!isIdentifier(define.name) || define.value.find_first_of("\n\\") != std::string::npos) {
      return invalidInput("bad shader define '" + text + "' in " + key +
                          " (want NAME or NAME VALUE on one line)");
    }
    if (!names.insert(define.name).second) {
      return invalidInput("shader define " + define.name + " is given two values in " + key);
    }
  }
  return {};
}

// ---------------------------------------------------------------------------------------------
// Source assembly

// Where shader text comes from: explicit sources first (tests), then the embedded table.
class SourceSet {
 public:
  explicit SourceSet(const std::map<std::string, std::string>* overrides = nullptr) : overrides_(overrides) {}
  std::optional<std::string_view> find(const std::string& path) const {
    if (overrides_ != nullptr) {
      if (auto found = overrides_->find(path); found != overrides_->end()) return found->second;
    }
    if (const ShaderSource* embedded = findShader(path)) return std::string_view(embedded->text);
    return std::nullopt;
  }

 private:
  const std::map<std::string, std::string>* overrides_;
};

// One stage's text as handed to the driver, and what its source-string numbers stand for.
struct StageSource {
  std::string text;
  std::vector<std::string> files;  // number -> path under shaders/; 0 is the generated preamble
};

// `#include "name"` -> name; nullopt for other lines; an error for a malformed include.
Result<std::optional<std::string>> parseInclude(std::string_view line) {
  std::string_view rest = trim(line);
  if (rest.empty() || rest[0] != '#') return std::optional<std::string>();
  rest = trim(rest.substr(1));
  const bool isInclude =
      rest.substr(0, 7) == "include" && (rest.size() == 7 || rest[7] == ' ' || rest[7] == '\t' || rest[7] == '"');
  if (!isInclude) return std::optional<std::string>();
  rest = trim(rest.substr(7));
  const auto close = rest.size() > 1 && rest[0] == '"' ? rest.find('"', 1) : std::string_view::npos;
  if (close == std::string_view::npos) return invalidInput("malformed #include (write #include \"file.glsl\")");
  const std::string_view tail = trim(rest.substr(close + 1));
  if (!tail.empty() && tail.substr(0, 2) != "//") return invalidInput("unexpected text after #include");
  return std::optional<std::string>(std::string(rest.substr(1, close - 1)));
}

bool isVersionDirective(std::string_view line) {
  line = trim(line);
  if (line.empty() || line[0] != '#') return false;
  return trim(line.substr(1)).substr(0, 7) == "version";
}

// Expands includes recursively. Includes are expanded before the GLSL preprocessor runs, so an
// include inside `#if 0` is still read; files use include guards to be included twice.
class Assembler {
 public:
  explicit Assembler(const SourceSet& sources) : sources_(sources) {}

  Result<StageSource> assemble(const std::string& path, const std::vector<std::string>& defines) {
    result_ = {};
    result_.files.push_back(path);  // the preamble is reported against the stage file
    result_.text = "#version 450 core\n";
    for (const std::string& define : defines) result_.text += "#define " + define + "\n";
    const auto text = sources_.find(path);
    if (!text) return invalidInput("shader " + path + " is not in the embedded table", {shadersPath(path), ""});
    BAKE_RETURN_IF_ERROR(appendFile(path, *text));
    return std::move(result_);
  }

 private:
  // `#line` that makes the next line read as line `line` of source string `number`.
  static std::string lineDirective(int number, int line) {
    return "#line " + std::to_string(number * kLinesPerFile + line) + " " + std::to_string(number) + "\n";
  }

  Status appendFile(const std::string& path, std::string_view text) {
    // A file included twice gets a new number each time: numbers stand for places in the text.
    const int fileNumber = int(result_.files.size());
    result_.files.push_back(path);
    stack_.push_back(path);
    result_.text += lineDirective(fileNumber, 1);
    const auto lines = splitLines(text);
    if (lines.size() >= std::size_t(kLinesPerFile)) {
      return invalidInput("shader has too many lines (the limit is " + std::to_string(kLinesPerFile - 1) + ")",
                          {shadersPath(path), ""});
    }
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const int lineNumber = int(i) + 1;
      const Location here{shadersPath(path), lineElement(lineNumber)};
      if (isVersionDirective(lines[i])) {
        return invalidInput("shaders must not declare #version; the library adds #version 450 core", here);
      }
      auto include = parseInclude(lines[i]);
      if (!include) return Status(include.status().code(), include.status().message(), here);
      if (!include->has_value()) {
        result_.text.append(lines[i]);
        result_.text += '\n';
        continue;
      }
      BAKE_RETURN_IF_ERROR(appendInclude(path, **include, here));
      result_.text += lineDirective(fileNumber, lineNumber + 1);  // back in this file, after the include
    }
    stack_.pop_back();
    return {};
  }

  Status appendInclude(const std::string& includer, const std::string& name, const Location& here) {
    BAKE_ASSIGN_OR_RETURN(const std::string path, resolve(includer, name, here));
    if (std::find(stack_.begin(), stack_.end(), path) != stack_.end()) {
      std::string cycle;
      for (auto at = std::find(stack_.begin(), stack_.end(), path); at != stack_.end(); ++at) cycle += *at + " -> ";
      return invalidInput("include cycle: " + cycle + path, here);
    }
    return appendFile(path, *sources_.find(path));
  }

  // An include names a file next to the includer, or else a path from the shaders/ root.
  Result<std::string> resolve(const std::string& includer, const std::string& name, const Location& here) const {
    namespace fs = std::filesystem;
    const fs::path folder = fs::path(includer).parent_path();
    for (const fs::path& candidate : {folder / name, fs::path(name)}) {
      const std::string path = candidate.lexically_normal().generic_string();
      if (candidate.is_absolute() || path.empty() || path.substr(0, 2) == "..") continue;
      if (sources_.find(path)) return path;
    }
    return invalidInput("included shader \"" + name + "\" is not in the embedded table (looked next to " +
                            includer + " and under shaders/)",
                        here);
  }

  const SourceSet& sources_;
  StageSource result_;
  std::vector<std::string> stack_;  // files being expanded, outermost first
};

// ---------------------------------------------------------------------------------------------
// Driver messages

struct DriverMessage {
  int source = 0, line = 0;
  std::string text;  // "error: `y' undeclared"
};

// Info-log lines in the formats of Mesa ("0:12(5): error: ..."), NVIDIA ("0(12) : error C1008: ...")
// and AMD ("ERROR: 0:12: ...").
std::optional<DriverMessage> parseLogLine(const std::string& line) {
  static const std::regex mesa(R"(^\s*(\d+):(\d+)\(\d+\):\s*(.*)$)");
  static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
  static const std::regex amd(R"(^\s*(ERROR|WARNING):\s*(\d+):(\d+):\s*(.*)$)");
  std::smatch match;
  if (std::regex_match(line, match, mesa) || std::regex_match(line, match, nvidia)) {
    return DriverMessage{std::stoi(match[1]), std::stoi(match[2]), match[3]};
  }
  if (std::regex_match(line, match, amd)) {
    return DriverMessage{std::stoi(match[2]), std::stoi(match[3]), match[1].str() + ": " + match[4].str()};
  }
  return std::nullopt;
}

// Maps a driver (string, line) to our file and line. The line block decides the file; the string
// number is only a fallback for drivers that ignore the line numbers we set.
std::optional<Location> mapToFile(const StageSource& stage, int source, int line) {
  int file = line / kLinesPerFile, lineInFile = line % kLinesPerFile;
  if (file == 0 && source > 0) file = source;
  if (file < 0 || std::size_t(file) >= stage.files.size()) return std::nullopt;
  if (file == 0) return Location{shadersPath(stage.files[0]), "preamble line " + std::to_string(lineInFile)};
  return Location{shadersPath(stage.files[std::size_t(file)]), lineElement(lineInFile)};
}

// The severity is the text before the first colon: "error", "preprocessor error", "error C1008",
// "ERROR"; a warning that merely mentions an error is not one.
bool isError(const std::string& text) {
  std::string severity = text.substr(0, text.find(':'));
  std::transform(severity.begin(), severity.end(), severity.begin(), [](unsigned char c) { return std::tolower(c); });
  return severity.find("error") != std::string::npos;
}

// The first error becomes the Status location; later ones are listed in the message, mapped too.
Status compileError(const StageSource& stage, const std::string& log, const std::string& context) {
  std::optional<Location> first;
  std::string message, more;
  for (std::string_view rawLine : splitLines(log)) {
    const std::string line(trim(rawLine));
    const auto parsed = parseLogLine(line);
    if (!parsed || !isError(parsed->text)) continue;
    const auto where = mapToFile(stage, parsed->source, parsed->line);
    if (!where) continue;
    if (!first) {
      first = where;
      message = parsed->text;
    } else {
      more += "\n  " + where->file + ": " + where->element + ": " + parsed->text;
    }
  }
  if (!first) {
    return invalidInput("shader failed to compile (" + context + "); driver log:\n" + log,
                        {shadersPath(stage.files[0]), ""});
  }
  return invalidInput(message + " (" + context + ")" + more, *first);
}

std::string shaderInfoLog(GLuint shader) {
  GLint length = 0;  // includes the terminating NUL, or 0 for no log
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(std::size_t(std::max(length, 1)), '\0');
  GLsizei written = 0;
  glGetShaderInfoLog(shader, GLsizei(log.size()), &written, log.data());
  log.resize(std::size_t(written));
  return log;
}

std::string programInfoLog(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(std::size_t(std::max(length, 1)), '\0');
  GLsizei written = 0;
  glGetProgramInfoLog(program, GLsizei(log.size()), &written, log.data());
  log.resize(std::size_t(written));
  return log;
}

// ---------------------------------------------------------------------------------------------
// Compiling and linking

struct Stage {
  GLenum type;
  const char* name;
  const std::string* path;
};

// Pipeline order; also the order of paths in a key.
std::vector<Stage> stagesOf(const ProgramDesc& desc) {
  std::vector<Stage> stages;
  const Stage all[] = {{GL_VERTEX_SHADER, "vertex", &desc.vertex},
                       {GL_TESS_CONTROL_SHADER, "tessellation control", &desc.tessControl},
                       {GL_TESS_EVALUATION_SHADER, "tessellation evaluation", &desc.tessEvaluation},
                       {GL_GEOMETRY_SHADER, "geometry", &desc.geometry},
                       {GL_FRAGMENT_SHADER, "fragment", &desc.fragment}};
  for (const Stage& stage : all) {
    if (!stage.path->empty()) stages.push_back(stage);
  }
  return stages;
}

Result<GLuint> compileStage(const Stage& stage, const StageSource& source, const std::string& key) {
  const GLuint shader = glCreateShader(stage.type);
  if (shader == 0) return internalError("glCreateShader failed (is a GL context current?)");
  const GLchar* text = source.text.c_str();
  const GLint length = GLint(source.text.size());
  glShaderSource(shader, 1, &text, &length);
  glCompileShader(shader);
  GLint compiled = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
  if (compiled == GL_TRUE) return shader;
  Status error = compileError(source, shaderInfoLog(shader), std::string(stage.name) + " stage of " + key);
  glDeleteShader(shader);
  return error;
}

Result<GLuint> linkProgram(const std::vector<GLuint>& shaders, const std::string& key) {
  const GLuint program = glCreateProgram();
  if (program == 0) return internalError("glCreateProgram failed (is a GL context current?)");
  for (GLuint shader : shaders) glAttachShader(program, shader);
  glLinkProgram(program);
  for (GLuint shader : shaders) glDetachShader(program, shader);
  GLint linked = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (linked == GL_TRUE) return program;
  Status error =
      invalidInput("shader program " + key + " failed to link: " + std::string(trim(programInfoLog(program))));
  glDeleteProgram(program);
  return error;
}

Result<GLuint> buildProgram(const Variant& variant, const SourceSet& sources) {
  const std::string key = variant.key();
  const std::vector<Stage> stages = stagesOf(variant.program);
  if (variant.program.vertex.empty() || variant.program.fragment.empty()) {
    return invalidInput("shader program " + key + " needs a vertex and a fragment stage");
  }
  const std::vector<std::string> defines = canonicalDefines(variant.defines);
  BAKE_RETURN_IF_ERROR(checkDefines(defines, key));
  // Assemble every stage before compiling any, so source errors cost no GL objects.
  std::vector<StageSource> assembled;
  for (const Stage& stage : stages) {
    Assembler assembler(sources);
    BAKE_ASSIGN_OR_RETURN(StageSource source, assembler.assemble(*stage.path, defines));
    assembled.push_back(std::move(source));
  }
  std::vector<GLuint> shaders;
  Status compiled;
  for (std::size_t i = 0; i < stages.size() && compiled.isOk(); ++i) {
    auto shader = compileStage(stages[i], assembled[i], key);
    if (shader) shaders.push_back(*shader);
    else compiled = shader.takeStatus();
  }
  Result<GLuint> program = compiled.isOk() ? linkProgram(shaders, key) : Result<GLuint>(std::move(compiled));
  for (GLuint shader : shaders) glDeleteShader(shader);
  return program;
}

}  // namespace

const ShaderSource* findShader(const std::string& path) {
  for (const ShaderSource& source : embeddedShaders()) {
    if (path == source.path) return &source;
  }
  return nullptr;
}

std::string Variant::key() const {
  std::string key;
  for (const Stage& stage : stagesOf(program)) key += (key.empty() ? "" : "+") + *stage.path;
  key += "[";
  const std::vector<std::string> canonical = canonicalDefines(defines);
  for (std::size_t i = 0; i < canonical.size(); ++i) key += (i ? "," : "") + canonical[i];
  return key + "]";
}

ShaderLibrary::~ShaderLibrary() {
  // Program names belong to the context they were made in. With no context current there is
  // nothing safe to call (the context, if destroyed, took the programs with it).
  if (!contextIsCurrent()) return;
  for (const auto& [key, program] : programs_) glDeleteProgram(program);
  for (GLuintHandle program : uncached_) glDeleteProgram(program);
}

Result<GLuintHandle> ShaderLibrary::program(const Variant& variant) {
  const std::string key = variant.key();
  if (auto found = programs_.find(key); found != programs_.end()) return found->second;
  BAKE_ASSIGN_OR_RETURN(const GLuint program, buildProgram(variant, SourceSet()));
  programs_.emplace(key, program);
  return program;
}

std::vector<std::string> ShaderLibrary::compiledVariants() const {
  std::vector<std::string> keys;
  for (const auto& [key, program] : programs_) keys.push_back(key);
  return keys;  // std::map keeps them sorted
}

Result<GLuintHandle> ShaderLibrary::programFromSources(const Variant& variant,
                                                       const std::map<std::string, std::string>& sources) {
  BAKE_ASSIGN_OR_RETURN(const GLuint program, buildProgram(variant, SourceSet(&sources)));
  uncached_.push_back(program);
  return program;
}

}  // namespace bake::gl
