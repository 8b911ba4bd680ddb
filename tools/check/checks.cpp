// iecoop-check: the checks. One walk over the user's declarations and code in a translation
// unit; iecoop's own headers and the system headers are skipped whole.
#include "checks.hpp"

#include <algorithm>
#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cursor.hpp"

namespace iecoop_check {
namespace {

/// What a class is to the checks: an iecoop block or not, and the blocks it derives from
/// that the user wrote (nearest first: its base, then its base's base...).
struct class_info {
  bool is_block = false;
  std::vector<CXCursor> bases;
};

/// A method's variables: the parameter `args<Vars> in` and the names of Vars's fields.
struct method_variables {
  std::string parameter;
  std::set<std::string> fields;
};

/// Check 6: a call, in a block's FB_Init, FB_Reinit or FB_Exit, of a method of the block
/// (through THIS^), or an access to one of its properties, to be matched with the blocks that
/// extend it once every class of the translation unit is known.
struct lifecycle_call {
  CXCursor at;                   // the member expression: `Meth`, `this->Meth`, `Maximum`
  CXCursor lifecycle;            // the FB_Init, FB_Reinit or FB_Exit the call is in
  CXCursor owner;                // its block
  std::vector<CXCursor> called;  // the method, or the property's accessors the access calls
  std::string property;          // the property's name, or empty for a method
  std::string access;            // for a property: "reads", "sets" or "reads and sets"
};

/// The function whose code the walk is in (a lambda's code is its enclosing function's).
struct code_context {
  CXCursor function;
  CXCursor owner_class;                // the class of a member function, else null
  std::vector<method_variables> vars;  // for a method of a block: its args<Vars> parameters
};

// Lifecycle methods are called by iecoop through the block's own type, not dispatched.
const std::set<std::string> not_dispatched = {"FB_Init", "FB_Reinit", "FB_Exit"};

const std::set<std::string> assignment_operators = {
    "operator=",  "operator+=", "operator-=",  "operator*=",  "operator/=", "operator%=", "operator&=",
    "operator|=", "operator^=", "operator<<=", "operator>>=", "operator++", "operator--"};

class checker {
 public:
  explicit checker(CXTranslationUnit unit) : unit_(unit) {}

  std::vector<finding> run() {
    const CXCursor root = clang_getTranslationUnitCursor(unit_);
    find_library_dir(root);
    for (const CXCursor child : children(root)) walk(child);
    report_lifecycle_calls();
    return std::move(findings_);
  }

 private:
  // --- Where things are ---------------------------------------------------------------

  /// iecoop's include directory (…/include/iecoop): where the class template iecoop::local
  /// or iecoop::function_block is defined. Everything below it is iecoop's, not the user's.
  void find_library_dir(CXCursor root) {
    for (const CXCursor top : children(root)) {
      if (clang_getCursorKind(top) != CXCursor_Namespace || spelling(top) != "iecoop") continue;
      for (const CXCursor member : children(top)) {
        if (clang_getCursorKind(member) != CXCursor_ClassTemplate || clang_isCursorDefinition(member) == 0) continue;
        const std::string name = spelling(member);
        if (name != "local" && name != "function_block") continue;
        CXFile file = nullptr;
        clang_getExpansionLocation(clang_getCursorLocation(member), &file, nullptr, nullptr, nullptr);
        // Both are declared in …/include/iecoop/pou/: the library is that directory's parent.
        const std::string path = real_path(file);
        const std::size_t slash = path.rfind('/');
        const std::size_t parent =
            slash == std::string::npos || slash == 0 ? std::string::npos : path.rfind('/', slash - 1);
        if (parent != std::string::npos) {
          library_dir_ = path.substr(0, parent + 1);
          return;
        }
      }
    }
  }

  static std::string real_path(CXFile file) {
    if (file == nullptr) return {};
    std::string path = text(clang_File_tryGetRealPathName(file));
    if (path.empty()) path = text(clang_getFileName(file));
    return path;
  }

  /// A file the user wrote: not a system header, not one of iecoop's headers.
  bool is_user_location(CXSourceLocation where) {
    if (clang_Location_isInSystemHeader(where) != 0) return false;
    CXFile file = nullptr;
    clang_getExpansionLocation(where, &file, nullptr, nullptr, nullptr);
    if (file == nullptr) return false;
    const auto known = user_files_.find(file);
    if (known != user_files_.end()) return known->second;
    const bool user = library_dir_.empty() || real_path(file).rfind(library_dir_, 0) != 0;
    user_files_.emplace(file, user);
    return user;
  }

  static location location_of(CXCursor c) {
    CXFile file = nullptr;
    unsigned line = 0;
    unsigned column = 0;
    clang_getExpansionLocation(clang_getCursorLocation(c), &file, &line, &column, nullptr);
    return location{file != nullptr ? text(clang_getFileName(file)) : std::string("<unknown>"), line, column};
  }

  void report(CXCursor at, std::string message, std::vector<note> notes = {}) {
    if (!is_user_location(clang_getCursorLocation(at))) return;
    findings_.push_back(finding{location_of(at), std::move(message), std::move(notes)});
  }

  // --- Classes ------------------------------------------------------------------------

  /// Whether `cls` is an iecoop block, and the user's blocks it derives from. A block
  /// derives, directly or through other blocks, from iecoop::function_block<>,
  /// iecoop::program<> or iecoop::extends<> (whose second argument is the base block).
  const class_info& info(CXCursor cls) {
    cls = members_of(cls);
    const std::string key = usr(cls);
    const auto known = classes_.find(key);
    if (known != classes_.end()) return known->second;
    classes_[key] = class_info{};  // a class that (wrongly) reaches itself ends here
    class_info result;
    const auto add_base = [&](CXCursor base) {
      base = members_of(base);
      const class_info& base_info = info(base);
      if (!base_info.is_block) return;
      result.is_block = true;
      result.bases.push_back(base);
      result.bases.insert(result.bases.end(), base_info.bases.begin(), base_info.bases.end());
    };
    for (const CXCursor child : children(cls)) {
      if (clang_getCursorKind(child) != CXCursor_CXXBaseSpecifier) continue;
      const CXType base_type = clang_getCursorType(child);
      const CXCursor base = class_of(base_type);
      if (is_null(base)) continue;
      if (in_namespace_iecoop(base)) {
        const std::string name = spelling(base);
        if (name == "function_block" || name == "program") {
          result.is_block = true;
        } else if (name == "extends") {
          result.is_block = true;
          const CXCursor extended = class_of(template_argument(base_type, 1));
          if (!is_null(extended) && !in_namespace_iecoop(extended)) add_base(extended);
        }
      } else {
        add_base(base);
      }
    }
    return classes_[key] = std::move(result);
  }

  /// Whether `cls` is `ancestor` or derives from it (through the user's blocks).
  bool is_or_derives_from(CXCursor cls, CXCursor ancestor) {
    const std::string wanted = usr(members_of(ancestor));
    if (usr(members_of(cls)) == wanted) return true;
    const class_info& cls_info = info(cls);
    return std::any_of(cls_info.bases.begin(), cls_info.bases.end(),
                       [&](CXCursor base) { return usr(base) == wanted; });
  }

  /// A class's name as its block's code writes it: with the classes it is nested in.
  static std::string class_name(CXCursor cls) {
    std::string name = spelling(members_of(cls));
    for (CXCursor outer = clang_getCursorSemanticParent(cls); is_class_kind(clang_getCursorKind(outer));
         outer = clang_getCursorSemanticParent(outer)) {
      name = spelling(outer) + "::" + name;
    }
    return name;
  }

  /// A member function that dispatch is about: not static, not an operator, constructor,
  /// destructor or conversion, not a lifecycle method.
  static bool is_dispatchable_method(CXCursor c) {
    const CXCursorKind kind = clang_getCursorKind(c);
    if (kind != CXCursor_CXXMethod && kind != CXCursor_FunctionTemplate) return false;
    const std::string name = spelling(c);
    if (is_operator_name(name) || not_dispatched.count(name) != 0) return false;
    return clang_CXXMethod_isStatic(c) == 0;
  }

  /// `operator=`, `operator()`, `operator new`, not a method named `operatorPanel`.
  static bool is_operator_name(const std::string& name) {
    constexpr std::size_t length = sizeof("operator") - 1;
    if (name.size() <= length || name.compare(0, length, "operator") != 0) return false;
    const char next = name[length];
    return !((next >= 'a' && next <= 'z') || (next >= 'A' && next <= 'Z') || (next >= '0' && next <= '9') ||
             next == '_');
  }

  /// Check 1 (a method hides its base's instead of overriding it) and check 4 (a variable
  /// declared again) for a block class.
  void check_block_class(CXCursor cls) {
    const class_info& cls_info = info(cls);
    if (!cls_info.is_block || cls_info.bases.empty()) return;
    const std::vector<CXCursor> bases = cls_info.bases;  // info() may grow the map
    for (const CXCursor member : children(cls)) {
      if (is_dispatchable_method(member)) {
        check_hiding(cls, member, bases);
      } else if (clang_getCursorKind(member) == CXCursor_FieldDecl) {
        check_redeclared(cls, member, bases);
      }
    }
  }

  /// The USRs of the methods `method` overrides, directly or through the methods it overrides
  /// (extends<> has a body() of its own between two blocks' bodies), and of the templates'
  /// members they were instantiated from.
  static void add_overridden(CXCursor method, std::set<std::string>& result, int depth = 0) {
    CXCursor* overridden = nullptr;
    unsigned count = 0;
    clang_getOverriddenCursors(method, &overridden, &count);
    for (unsigned i = 0; i < count; ++i) {
      if (!result.insert(usr(overridden[i])).second || depth > 32) continue;
      const CXCursor from = clang_getSpecializedCursorTemplate(overridden[i]);
      if (!is_null(from)) result.insert(usr(from));
      add_overridden(overridden[i], result, depth + 1);
    }
    clang_disposeOverriddenCursors(overridden);
  }

  void check_hiding(CXCursor cls, CXCursor method, const std::vector<CXCursor>& bases) {
    const std::string name = spelling(method);
    std::set<std::string> overridden;
    add_overridden(method, overridden);
    for (const CXCursor base : bases) {
      std::vector<CXCursor> same_name;
      for (const CXCursor member : children(base)) {
        if (is_dispatchable_method(member) && spelling(member) == name) same_name.push_back(member);
      }
      if (same_name.empty()) continue;  // the name is declared further up, if anywhere
      if (std::any_of(same_name.begin(), same_name.end(), [&](CXCursor m) { return overridden.count(usr(m)) != 0; })) {
        return;
      }
      const auto non_virtual = std::find_if(same_name.begin(), same_name.end(),
                                            [](CXCursor m) { return clang_CXXMethod_isVirtual(m) == 0; });
      const std::string derived = class_name(cls) + "::" + name;
      const std::string hidden = class_name(base) + "::" + name;
      if (non_virtual != same_name.end()) {
        report(method,
               derived + " hides " + hidden + ", which is not virtual, so a call through a reference to " +
                   class_name(base) + " runs " + hidden + " (in CODESYS every METHOD is virtual); declare " + hidden +
                   " virtual, and " + derived + " override",
               {note{location_of(*non_virtual), hidden + " is declared here"}});
      } else {
        report(method,
               derived + " does not override " + hidden +
                   " (their parameters differ), so it hides it, and a call "
                   "through a reference to " +
                   class_name(base) + " runs " + hidden + "; give " + derived + " the parameters of " + hidden +
                   " and mark it override",
               {note{location_of(same_name.front()), hidden + " is declared here"}});
      }
      return;
    }
  }

  void check_redeclared(CXCursor cls, CXCursor field, const std::vector<CXCursor>& bases) {
    const std::string name = spelling(field);
    if (name.empty()) return;
    for (const CXCursor base : bases) {
      for (const CXCursor member : children(base)) {
        if (clang_getCursorKind(member) != CXCursor_FieldDecl || spelling(member) != name) continue;
        const std::string base_variable = class_name(base) + "::" + name;
        report(field,
               class_name(cls) + " declares " + name + ", which its base " + class_name(base) +
                   " already declares, so the code of the two blocks uses two different variables (CODESYS rejects "
                   "a variable that the base block declares); remove " +
                   class_name(cls) + "::" + name + " and use " + base_variable,
               {note{location_of(member), base_variable + " is declared here"}});
        return;
      }
    }
  }

  // --- Initial values -----------------------------------------------------------------

  /// A C++ scalar (an enum, an arithmetic type, a pointer) or a built-in array of them: a
  /// variable of it that is default-initialised is undefined.
  static bool is_raw_scalar(CXType t) {
    t = clang_getCanonicalType(t);
    while (t.kind == CXType_ConstantArray) t = clang_getCanonicalType(clang_getArrayElementType(t));
    if (t.kind == CXType_Enum || t.kind == CXType_Pointer || t.kind == CXType_MemberPointer) return true;
    return t.kind >= CXType_FirstBuiltin && t.kind <= CXType_LastBuiltin && t.kind != CXType_Void;
  }

  /// A declaration's initialiser: an expression among its children (`= E::A`, `{}`).
  static bool has_initialiser(CXCursor declaration) {
    const std::vector<CXCursor> parts = children(declaration);
    return std::any_of(parts.begin(), parts.end(),
                       [](CXCursor part) { return clang_isExpression(clang_getCursorKind(part)) != 0; });
  }

  static std::string type_spelling(CXCursor declaration) {
    return text(clang_getTypeSpelling(clang_getCursorType(declaration)));
  }

  /// Check 5: a member of a C++ scalar type without an initial value, in a block or a STRUCT
  /// (a class without constructors of its own) — or in a class whose constructors do not
  /// initialise it. Unions state their own constructor (docs/porting-guide.md) and are left out.
  void check_uninitialised_members(CXCursor cls) {
    if (clang_getCursorKind(cls) == CXCursor_ClassTemplate) return;  // its members' types are not known yet
    std::set<std::string> initialised;  // the members a constructor's initialiser list names
    bool has_constructor = false;       // other than the copy and move constructors
    for (const CXCursor member : children(cls)) {
      if (clang_getCursorKind(member) != CXCursor_Constructor) continue;
      if (clang_CXXConstructor_isCopyConstructor(member) != 0 || clang_CXXConstructor_isMoveConstructor(member) != 0) {
        continue;
      }
      has_constructor = true;
      for (const CXCursor part : children(member)) {
        if (clang_getCursorKind(part) == CXCursor_MemberRef) initialised.insert(usr(clang_getCursorReferenced(part)));
      }
    }
    if (has_constructor && !info(cls).is_block) return;  // a class of its own making, not a STRUCT
    for (const CXCursor member : children(cls)) {
      if (clang_getCursorKind(member) != CXCursor_FieldDecl || !is_raw_scalar(clang_getCursorType(member))) continue;
      if (has_initialiser(member) || initialised.count(usr(member)) != 0) continue;
      const std::string name = class_name(cls) + "::" + spelling(member);
      report(member, name + " (" + type_spelling(member) + ") has no initial value: C++ leaves it undefined wherever " +
                         class_name(cls) +
                         " is default-initialised (a local variable, a member of a block declared as one), where ST "
                         "starts it at 0, FALSE or its enumeration's first component; write its initial value (" +
                         spelling(member) + " = ...), or give it an IEC type (INT, BOOL, POINTER_TO<T>)");
    }
  }

  /// A function or lambda that takes a METHOD's or FUNCTION's variables (`args<Vars>`).
  static bool takes_args(CXCursor function) {
    const std::vector<CXCursor> parts = children(function);
    return std::any_of(parts.begin(), parts.end(), [](CXCursor part) {
      return clang_getCursorKind(part) == CXCursor_ParmDecl &&
             is_iecoop_class(class_of(clang_getCursorType(part)), "args");
    });
  }

  /// Check 5 for a local variable (ST's VAR_TEMP, a METHOD's or FUNCTION's VAR) of a C++
  /// scalar type without an initial value: of an enumeration anywhere, of another scalar in
  /// the code of a POU (a block's member function, a function or lambda taking args<Vars>; the
  /// C++ around a port, such as main()'s option parsing, is C++'s).
  void check_uninitialised_local(CXCursor variable, const code_context* context) {
    const CXType type = clang_getCursorType(variable);
    if (clang_Cursor_getStorageClass(variable) == CX_SC_Static || clang_Cursor_hasVarDeclGlobalStorage(variable) == 1) {
      check_static_enumeration(variable, type);
      return;
    }
    if (!is_raw_scalar(type) || has_initialiser(variable)) return;
    const bool pou_code =
        pou_code_depth_ > 0 ||
        (context != nullptr &&
         ((!is_null(context->owner_class) && info(context->owner_class).is_block) || takes_args(context->function)));
    if (clang_getCanonicalType(type).kind != CXType_Enum && !pou_code) return;
    const std::string where = context == nullptr && pou_code_depth_ > 0 ? "a FUNCTION" : context_name(context);
    report(variable, where + ": the local variable " + spelling(variable) + " (" + type_spelling(variable) +
                         ") has no initial value: C++ leaves it undefined until it is assigned, where ST starts a "
                         "variable at 0, FALSE or its enumeration's first component; write its initial value (" +
                         spelling(variable) + " = ...), or give it an IEC type (INT, BOOL, POINTER_TO<T>)");
  }

  /// The first enumerator of an enum type that is not 0 (where C++ zero-initialises a static
  /// variable of it and ST starts it at the first component), or a null cursor.
  static CXCursor first_enumerator_not_zero(CXType type) {
    type = clang_getCanonicalType(type);
    while (type.kind == CXType_ConstantArray) type = clang_getCanonicalType(clang_getArrayElementType(type));
    if (type.kind != CXType_Enum) return clang_getNullCursor();
    const CXCursor declaration = clang_getTypeDeclaration(type);
    for (const CXCursor enumerator : children(declaration)) {
      if (clang_getCursorKind(enumerator) != CXCursor_EnumConstantDecl) continue;
      return clang_getEnumConstantDeclValue(enumerator) != 0 ? enumerator : clang_getNullCursor();
    }
    return clang_getNullCursor();
  }

  /// Check 5 for a static variable (VAR_STAT, a global, a `static` local) of an enumeration
  /// whose first component is not 0: C++ zero-initialises it.
  void check_static_enumeration(CXCursor variable, CXType type) {
    if (clang_isCursorDefinition(variable) == 0 || has_initialiser(variable)) return;
    const CXCursor first = first_enumerator_not_zero(type);
    if (is_null(first)) return;
    report(variable, "the static variable " + spelling(variable) + " (" + type_spelling(variable) +
                         ") has no initial value: C++ zero-initialises it, to 0, which is not " + spelling(first) +
                         ", the first component where ST starts it; write its initial value (" + spelling(variable) +
                         " = ...)");
  }

  // --- Code ---------------------------------------------------------------------------

  /// The variables of a block's method, from its `args<Vars>` parameters.
  std::vector<method_variables> variables_of(CXCursor method, CXCursor owner) {
    std::vector<method_variables> result;
    if (is_null(owner) || !info(owner).is_block) return result;
    for (const CXCursor child : children(method)) {
      if (clang_getCursorKind(child) != CXCursor_ParmDecl) continue;
      const CXType type = clang_getCursorType(child);
      if (!is_iecoop_class(class_of(type), "args")) continue;
      const CXCursor vars = class_of(template_argument(type, 0));
      if (is_null(vars)) continue;
      method_variables entry{spelling(child), {}};
      for (const CXCursor field : children(members_of(vars))) {
        if (clang_getCursorKind(field) == CXCursor_FieldDecl) entry.fields.insert(spelling(field));
      }
      result.push_back(std::move(entry));
    }
    return result;
  }

  static std::string context_name(const code_context* context) {
    if (context == nullptr) return "code outside any block";
    std::string name = spelling(context->function) + "()";
    if (!is_null(context->owner_class)) name = class_name(context->owner_class) + "::" + name;
    return name;
  }

  /// Whether `member` is declared by local<T, Owner> or by the base that gives every variable
  /// its `ref()`, `[]` and `->` (detail::variable_value).
  static bool is_variable_member(CXCursor member) {
    const CXCursor parent = clang_getCursorSemanticParent(member);
    return is_iecoop_class(parent, "local") || is_iecoop_class(parent, "variable_value");
  }

  /// The local<T, Owner> an expression writes into, if any: the expression itself, or the
  /// variable whose element or member it is (`fb.arr[1]`, `fb.pos->x`).
  static std::optional<std::pair<CXCursor, CXType>> written_local(CXCursor expression) {
    for (int depth = 0; depth < 64 && !is_null(expression); ++depth) {
      const CXType type = clang_getCursorType(expression);
      if (is_iecoop_class(class_of(type), "local")) return std::pair{expression, type};
      const std::vector<CXCursor> parts = children(expression);
      switch (clang_getCursorKind(expression)) {
        case CXCursor_UnexposedExpr:
        case CXCursor_ParenExpr:
          if (parts.size() != 1) return std::nullopt;
          expression = parts.front();
          break;
        case CXCursor_MemberRefExpr:  // a member of a structured value: its object
          if (parts.empty() || clang_getCursorKind(clang_getCursorReferenced(expression)) != CXCursor_FieldDecl) {
            return std::nullopt;
          }
          expression = parts.front();
          break;
        case CXCursor_ArraySubscriptExpr:
          if (parts.empty()) return std::nullopt;
          expression = parts.front();
          break;
        case CXCursor_CallExpr: {  // an element (`[]`) or member (`->`) of the local itself
          const CXCursor callee = clang_getCursorReferenced(expression);
          const std::string name = spelling(callee);
          if ((name != "operator[]" && name != "operator->") || !is_variable_member(callee) ||
              clang_Cursor_getNumArguments(expression) < 1) {
            return std::nullopt;
          }
          expression = clang_Cursor_getArgument(expression, 0);
          break;
        }
        default: return std::nullopt;
      }
    }
    return std::nullopt;
  }

  /// Check 2: a block's VAR (local<T, Owner>) written outside Owner and the blocks derived
  /// from it. `call` is an assignment, `ref()` on a local, or `"name"_ >> target`.
  void check_write(CXCursor call, const code_context* context) {
    const CXCursor callee = clang_getCursorReferenced(call);
    if (is_null(callee)) return;
    const std::string name = spelling(callee);
    std::optional<std::pair<CXCursor, CXType>> target;
    std::string how;
    if (assignment_operators.count(name) != 0) {
      if (clang_Cursor_getNumArguments(call) < 1) return;
      target = written_local(clang_Cursor_getArgument(call, 0));
    } else if (name == "ref" && is_variable_member(callee)) {
      const std::vector<CXCursor> parts = children(call);
      if (parts.empty()) return;
      const std::vector<CXCursor> object = children(parts.front());  // the MemberRefExpr `x.ref`
      if (object.empty()) return;                                    // this->ref(): inside local itself
      target = written_local(object.front());
      how = " through ref()";
    } else if (name == "operator>>" && is_iecoop_class(clang_getCursorSemanticParent(callee), "param_name")) {
      if (clang_Cursor_getNumArguments(call) < 2) return;
      target = written_local(clang_Cursor_getArgument(call, 1));
      how = " with =>";
    }
    if (target) check_target(*target, how, context);
  }

  /// Reports a write into `target` (an expression of type local<T, Owner>) unless the code
  /// is Owner's or a derived block's.
  void check_target(const std::pair<CXCursor, CXType>& target, const std::string& how, const code_context* context) {
    const CXCursor owner = class_of(template_argument(target.second, 1));
    if (is_null(owner)) return;
    if (context != nullptr && !is_null(context->owner_class) && is_or_derives_from(context->owner_class, owner)) return;
    const std::string variable = spelling(target.first);
    const std::string block = class_name(owner);
    report(target.first, context_name(context) + " writes " + variable + ", a VAR of " + block + "," + how +
                             " from outside the block (CODESYS lets only " + block +
                             " and the blocks that extend it write its VAR); write it in a method of " + block +
                             ", or make it a VAR_INPUT (a plain member listed in VAR_INPUT)");
  }

  /// The spelling of a built-in operator expression's operator: the token after its first
  /// operand (binary), or its first or last token (unary).
  std::string operator_spelling(CXCursor expression) {
    const std::vector<CXCursor> operands = children(expression);
    if (operands.empty()) return {};
    CXToken* tokens = nullptr;
    unsigned count = 0;
    clang_tokenize(unit_, clang_getCursorExtent(expression), &tokens, &count);
    std::string result;
    if (clang_getCursorKind(expression) == CXCursor_UnaryOperator) {
      if (count > 0) {
        result = text(clang_getTokenSpelling(unit_, tokens[0]));
        if (result != "++" && result != "--") result = text(clang_getTokenSpelling(unit_, tokens[count - 1]));
      }
    } else {
      unsigned operand_end = 0;
      clang_getExpansionLocation(clang_getRangeEnd(clang_getCursorExtent(operands.front())), nullptr, nullptr, nullptr,
                                 &operand_end);
      for (unsigned i = 0; i < count; ++i) {
        unsigned offset = 0;
        clang_getExpansionLocation(clang_getTokenLocation(unit_, tokens[i]), nullptr, nullptr, nullptr, &offset);
        if (offset >= operand_end) {
          result = text(clang_getTokenSpelling(unit_, tokens[i]));
          break;
        }
      }
    }
    clang_disposeTokens(unit_, tokens, count);
    return result;
  }

  /// Check 2 for C++'s built-in assignments (`=`, `+=`, `++`...), which write a plain
  /// member of a structured local (`fb.pos->i = 1` with an `int i`).
  void check_builtin_write(CXCursor expression, const code_context* context) {
    const CXCursorKind kind = clang_getCursorKind(expression);
    const std::vector<CXCursor> operands = children(expression);
    if (operands.empty()) return;
    const auto target = written_local(operands.front());
    if (!target) return;
    if (kind != CXCursor_CompoundAssignOperator) {
      const std::string op = operator_spelling(expression);
      if (op != "=" && op != "++" && op != "--") return;
    }
    check_target(*target, "", context);
  }

  /// Check 3: `x` alone in a method whose variables include an x means the method's x in ST.
  void check_shadowed(CXCursor reference, const code_context* context) {
    if (context == nullptr || context->vars.empty()) return;
    if (!children(reference).empty()) return;  // `this->x`, `in.x`, `other.x`: qualified
    const CXCursor field = clang_getCursorReferenced(reference);
    if (clang_getCursorKind(field) != CXCursor_FieldDecl) return;
    const std::string name = spelling(field);
    for (const method_variables& vars : context->vars) {
      if (vars.fields.count(name) == 0) continue;
      const std::string method = class_name(context->owner_class) + "::" + spelling(context->function);
      report(reference, "in " + method + ", " + name + " is the block's variable, but " + spelling(context->function) +
                            " declares its own " + name + ", and ST's " + name + " means that one here; write " +
                            vars.parameter + "." + name + " for the method's variable, or this->" + name +
                            " for the block's (THIS^." + name + ")");
      return;
    }
  }

  // --- Virtual calls in FB_Init, FB_Reinit, FB_Exit (check 6) --------------------------

  /// The lifecycle method (FB_Init, FB_Reinit, FB_Exit) of a block whose code the walk is in.
  bool in_lifecycle_method(const code_context* context) {
    return context != nullptr && !is_null(context->owner_class) &&
           not_dispatched.count(spelling(context->function)) != 0 && info(context->owner_class).is_block;
  }

  static CXCursor strip(CXCursor expression) {
    for (int depth = 0; depth < 16; ++depth) {
      const CXCursorKind kind = clang_getCursorKind(expression);
      if (kind != CXCursor_UnexposedExpr && kind != CXCursor_ParenExpr) break;
      const std::vector<CXCursor> parts = children(expression);
      if (parts.size() != 1) break;
      expression = parts.front();
    }
    return expression;
  }

  /// A member expression on the block itself, dispatched: `M` or `this->M` or `(*this).M`
  /// (ST's `M` and `THIS^.M`), not `FB_A::M` (qualified: not dispatched) nor `other.M`.
  static bool is_dispatched_on_this(CXCursor member_expression) {
    const std::vector<CXCursor> parts = children(member_expression);
    for (const CXCursor part : parts) {
      const CXCursorKind kind = clang_getCursorKind(part);
      if (kind == CXCursor_TypeRef || kind == CXCursor_TemplateRef || kind == CXCursor_NamespaceRef) return false;
    }
    if (parts.empty()) return true;
    CXCursor object = strip(parts.front());
    if (clang_getCursorKind(object) == CXCursor_UnaryOperator) {  // `*this`
      const std::vector<CXCursor> operand = children(object);
      if (operand.size() != 1) return false;
      object = strip(operand.front());
    }
    return clang_getCursorKind(object) == CXCursor_CXXThisExpr;
  }

  /// `Maximum = v` (or `+=`, `++`...) on a property in a lifecycle method: the access sets it.
  void note_property_assignment(CXCursor call, const code_context* context) {
    if (!in_lifecycle_method(context)) return;
    const CXCursor callee = clang_getCursorReferenced(call);
    if (is_null(callee) || assignment_operators.count(spelling(callee)) == 0 ||
        clang_Cursor_getNumArguments(call) < 1) {
      return;
    }
    const CXCursor target = strip(clang_Cursor_getArgument(call, 0));
    if (clang_getCursorKind(target) == CXCursor_MemberRefExpr &&
        is_iecoop_class(class_of(clang_getCursorType(target)), "property")) {
      property_assigned_[clang_hashCursor(target)] = spelling(callee);
    }
  }

  /// The accessors of a property member (`property<T, &FB::p_Get, &FB::p_Set>`), as its
  /// declaration names them: those taking no parameter (Get) or one (Set).
  static void property_accessors(CXCursor field, std::vector<CXCursor>& getters, std::vector<CXCursor>& setters) {
    const auto visit = [&](const auto& self, CXCursor c, int depth) -> void {
      if (depth > 8) return;
      for (const CXCursor part : children(c)) {
        if (clang_getCursorKind(part) == CXCursor_DeclRefExpr) {
          const CXCursor accessor = clang_getCursorReferenced(part);
          if (clang_getCursorKind(accessor) == CXCursor_CXXMethod) {
            (clang_Cursor_getNumArguments(accessor) == 0 ? getters : setters).push_back(accessor);
          }
          continue;
        }
        if (clang_getCursorKind(part) == CXCursor_CallExpr) continue;  // the initializer `{this}`
        self(self, part, depth + 1);
      }
    };
    visit(visit, field, 0);
  }

  /// Check 6: notes a call of the block's own method, or an access to its property, inside
  /// its FB_Init, FB_Reinit or FB_Exit, dispatched on the block itself.
  void note_lifecycle_call(CXCursor member_expression, const code_context* context) {
    if (!in_lifecycle_method(context) || !is_dispatched_on_this(member_expression)) return;
    const CXCursor member = clang_getCursorReferenced(member_expression);
    lifecycle_call call{member_expression, context->function, context->owner_class, {}, {}, {}};
    if (clang_getCursorKind(member) == CXCursor_CXXMethod) {
      if (clang_CXXMethod_isVirtual(member) == 0) return;  // not dispatched (check 1 reports a hiding one)
      call.called.push_back(member);
    } else if (clang_getCursorKind(member) == CXCursor_FieldDecl &&
               is_iecoop_class(class_of(clang_getCursorType(member)), "property")) {
      std::vector<CXCursor> getters;
      std::vector<CXCursor> setters;
      property_accessors(member, getters, setters);
      const auto assigned = property_assigned_.find(clang_hashCursor(member_expression));
      const bool sets = assigned != property_assigned_.end();
      const bool reads = !sets || assigned->second != "operator=";
      if (reads) call.called.insert(call.called.end(), getters.begin(), getters.end());
      if (sets) call.called.insert(call.called.end(), setters.begin(), setters.end());
      call.property = spelling(member);
      call.access = reads && sets ? "reads and sets" : sets ? "sets" : "reads";
    } else {
      return;
    }
    lifecycle_calls_.push_back(std::move(call));
  }

  /// Whether `cls` itself declares a member function `name`.
  static bool declares_member(CXCursor cls, const std::string& name) {
    const std::vector<CXCursor> members = children(members_of(cls));
    return std::any_of(members.begin(), members.end(), [&](CXCursor m) {
      const CXCursorKind kind = clang_getCursorKind(m);
      return (kind == CXCursor_CXXMethod || kind == CXCursor_FunctionTemplate) && spelling(m) == name;
    });
  }

  /// The method of `cls` that overrides `method` (directly or through a block between them),
  /// or a null cursor.
  static CXCursor override_in(CXCursor cls, CXCursor method) {
    const std::string wanted = usr(method);
    for (const CXCursor member : children(cls)) {
      if (clang_getCursorKind(member) != CXCursor_CXXMethod) continue;
      std::set<std::string> overridden;
      add_overridden(member, overridden);
      if (overridden.count(wanted) != 0) return member;
    }
    return clang_getNullCursor();
  }

  /// Check 6 (CODESYS's SA0106): each noted call whose method a block derived from the
  /// caller's block overrides. iecoop runs every level's FB_Init and FB_Exit on the whole
  /// block, as CODESYS does: the call runs the derived block's code, for a level of it whose
  /// own FB_Init has not run yet (or whose FB_Exit has run already).
  void report_lifecycle_calls() {
    for (const lifecycle_call& call : lifecycle_calls_) {
      const std::string block = class_name(call.owner);
      const std::string lifecycle = spelling(call.lifecycle);
      std::vector<std::string> derived_names;
      std::vector<note> notes;
      std::string first_override;
      CXCursor first_class = clang_getNullCursor();
      std::string first_accessor;  // for a property: the accessor overridden
      for (const CXCursor derived : block_classes_) {
        if (usr(members_of(derived)) == usr(members_of(call.owner)) || !is_or_derives_from(derived, call.owner)) {
          continue;
        }
        for (const CXCursor called : call.called) {
          const CXCursor overriding = override_in(derived, called);
          if (is_null(overriding)) continue;
          const std::string name = class_name(derived) + "::" + spelling(overriding);
          if (first_override.empty()) {
            first_override = name;
            first_class = derived;
            first_accessor = spelling(called);
          }
          if (derived_names.empty() || derived_names.back() != class_name(derived)) {
            derived_names.push_back(class_name(derived));
          }
          notes.push_back(note{location_of(overriding), name + " overrides it here"});
        }
      }
      if (derived_names.empty()) continue;
      std::string derived_list = derived_names.front();
      for (std::size_t i = 1; i < derived_names.size(); ++i) {
        derived_list += (i + 1 == derived_names.size() ? " and " : ", ") + derived_names[i];
      }
      const std::string& first = derived_names.front();
      std::string what;
      if (call.property.empty()) {
        what = block + "::" + lifecycle + " calls " + spelling(call.called.front()) + ", which " + derived_list +
               (derived_names.size() == 1 ? " overrides" : " override");
      } else {
        what = block + "::" + lifecycle + " " + call.access + " the property " + call.property + ", whose accessor " +
               first_accessor + " " + derived_list + (derived_names.size() == 1 ? " overrides" : " override");
      }
      const bool own = declares_member(first_class, lifecycle);
      std::string when;
      std::string needs;
      if (lifecycle == "FB_Init") {
        when = own ? "before " + first + "::FB_Init has run"
                   : "before the FB_Init of any block extending " + block + " has run";
        needs = "set up in their FB_Init";
      } else if (lifecycle == "FB_Exit") {
        when = own ? "after " + first + "::FB_Exit has run"
                   : "after the FB_Exit of the blocks extending " + block + " has run";
        needs = "release in their FB_Exit";
      } else {
        when =
            "whose own FB_Reinit may not have finished, as a base's FB_Reinit runs where the derived one calls "
            "SUPER^.FB_Reinit()";
        needs = "restore in their FB_Reinit";
      }
      const std::string rule = lifecycle == "FB_Init"
                                   ? "CODESYS's static analysis rule SA0106, virtual method calls in FB_init"
                                   : "CODESYS's static analysis rule SA0106 reports such calls in FB_init";
      report(call.at,
             what + ": iecoop runs " + lifecycle + " on the whole block, as CODESYS does, so for an instance of " +
                 first + " it runs " + first_override + ", " + when + " (" + rule + "); make sure " + first_override +
                 " needs nothing that the blocks extending " + block + " " + needs + ", or do the work in " + block +
                 "::" + lifecycle + " itself or in a method that no block overrides",
             std::move(notes));
    }
  }

  // --- The lifecycle handed on: run_fb_init, run_fb_exit (check 7) ---------------------

  /// The first of `chain` (a block, then the blocks it derives from) that declares `name`.
  static CXCursor first_declaring(const std::vector<CXCursor>& chain, const std::string& name) {
    for (const CXCursor level : chain) {
      if (declares_member(level, name)) return level;
    }
    return clang_getNullCursor();
  }

  /// `= delete`: its last two tokens (libclang 14 has no clang_CXXMethod_isDeleted).
  bool is_deleted(CXCursor function) {
    CXToken* tokens = nullptr;
    unsigned count = 0;
    clang_tokenize(unit_, clang_getCursorExtent(function), &tokens, &count);
    const bool deleted = count >= 2 && text(clang_getTokenSpelling(unit_, tokens[count - 1])) == "delete" &&
                         text(clang_getTokenSpelling(unit_, tokens[count - 2])) == "=";
    clang_disposeTokens(unit_, tokens, count);
    return deleted;
  }

  /// Whether the code of `function` calls iecoop's `hook` (run_fb_init, run_fb_exit), or
  /// delegates to another constructor of `cls` (which is checked itself).
  static bool hands_on(CXCursor function, CXCursor cls, const char* hook) {
    const std::string block = usr(members_of(cls));
    const auto visit = [&](const auto& self, CXCursor c, int depth) -> bool {
      if (depth > 256) return false;
      for (const CXCursor part : children(c)) {
        // In a template, a call whose arguments depend on its parameters names the function
        // by an overloaded reference: run_fb_init(*this, std::forward<A>(a)...).
        if (clang_getCursorKind(part) == CXCursor_OverloadedDeclRef && spelling(part) == hook &&
            clang_getNumOverloadedDecls(part) > 0 && in_namespace_iecoop(clang_getOverloadedDecl(part, 0))) {
          return true;
        }
        if (clang_getCursorKind(part) == CXCursor_CallExpr) {
          const CXCursor callee = clang_getCursorReferenced(part);
          if (!is_null(callee) && spelling(callee) == hook && in_namespace_iecoop(callee)) return true;
          if (clang_getCursorKind(callee) == CXCursor_Constructor &&
              usr(members_of(clang_getCursorSemanticParent(callee))) == block) {
            return true;
          }
        }
        if (self(self, part, depth + 1)) return true;
      }
      return false;
    };
    return visit(visit, function, 0);
  }

  /// What a missing hook costs: for a block that EXTENDS another, a lifecycle fault at run
  /// time; for a block of its own, its FB_Init or FB_Exit never runs.
  static std::string lifecycle_consequence(CXCursor cls, CXCursor level, bool derived, const std::string& lifecycle) {
    if (!derived) {
      return class_name(level) + "::" + lifecycle + " does not run when an instance of " + class_name(cls) +
             (lifecycle == "FB_Init" ? " is constructed" : " ends");
    }
    return "no level's " + lifecycle + " runs on the whole block when an instance of " + class_name(cls) +
           (lifecycle == "FB_Init" ? " is constructed" : " ends") +
           " (iecoop reports a lifecycle fault at run time; it runs every level's " + lifecycle +
           " from the most derived block, as CODESYS runs them on the whole block)";
  }

  /// Check 7: a block that has, or EXTENDS a block that has, an FB_Init whose constructors do
  /// not call run_fb_init(*this, ...); the same for FB_Exit and its destructor.
  void check_lifecycle_hooks(CXCursor cls) {
    if (clang_getCursorKind(cls) == CXCursor_ClassTemplatePartialSpecialization) return;
    const class_info& cls_info = info(cls);
    if (!cls_info.is_block) return;
    std::vector<CXCursor> chain{cls};
    chain.insert(chain.end(), cls_info.bases.begin(), cls_info.bases.end());
    const bool derived = !cls_info.bases.empty();
    const std::string name = class_name(cls);

    const CXCursor init_level = first_declaring(chain, "FB_Init");
    if (!is_null(init_level)) {
      const std::string has = usr(members_of(init_level)) == usr(members_of(cls))
                                  ? name + " has an FB_Init"
                                  : name + " EXTENDS " + class_name(init_level) + ", which has an FB_Init";
      bool own_constructor = false;
      for (const CXCursor member : children(cls)) {
        const CXCursorKind kind = clang_getCursorKind(member);
        const bool constructor =
            kind == CXCursor_Constructor ||
            (kind == CXCursor_FunctionTemplate && clang_getTemplateCursorKind(member) == CXCursor_Constructor);
        if (!constructor) continue;
        if (kind == CXCursor_Constructor && (clang_CXXConstructor_isCopyConstructor(member) != 0 ||
                                             clang_CXXConstructor_isMoveConstructor(member) != 0)) {
          continue;
        }
        if (is_deleted(member)) continue;
        own_constructor = true;
        const CXCursor definition = clang_getCursorDefinition(member);
        if (clang_CXXMethod_isDefaulted(member) == 0) {
          if (is_null(definition)) continue;  // defined in another file: not seen here
          if (hands_on(definition, cls, "run_fb_init")) continue;
        }
        report(member, has + ", but this constructor of " + name + " does not call run_fb_init(*this, ...), so " +
                           lifecycle_consequence(cls, init_level, derived, "FB_Init") +
                           "; call run_fb_init(*this, <FB_Init parameters>) in it");
      }
      if (!own_constructor) {
        report(
            cls,
            has +
                ", but it has no constructor of its own that calls run_fb_init(*this, ...) (an implicit or inherited "
                "constructor cannot), so " +
                lifecycle_consequence(cls, init_level, derived, "FB_Init") + "; give it one: " +
                spelling(members_of(cls)) + "() { run_fb_init(*this); }, with the FB_Init parameters");
      }
    }

    const CXCursor exit_level = first_declaring(chain, "FB_Exit");
    if (!is_null(exit_level)) {
      const std::string has = usr(members_of(exit_level)) == usr(members_of(cls))
                                  ? name + " has an FB_Exit"
                                  : name + " EXTENDS " + class_name(exit_level) + ", which has an FB_Exit";
      const std::vector<CXCursor> members = children(cls);
      const auto destructor = std::find_if(members.begin(), members.end(),
                                           [](CXCursor m) { return clang_getCursorKind(m) == CXCursor_Destructor; });
      const std::string fix =
          "~" + spelling(members_of(cls)) + "()" + (derived ? " override" : "") + " { run_fb_exit(*this); }";
      if (destructor == members.end()) {
        report(cls, has + ", but it has no destructor of its own that calls run_fb_exit(*this), so " +
                        lifecycle_consequence(cls, exit_level, derived, "FB_Exit") + "; give it one: " + fix);
      } else {
        const CXCursor definition = clang_getCursorDefinition(*destructor);
        if (clang_CXXMethod_isDefaulted(*destructor) != 0 ||
            (!is_null(definition) && !hands_on(definition, cls, "run_fb_exit"))) {
          report(*destructor, has + ", but the destructor of " + name + " does not call run_fb_exit(*this), so " +
                                  lifecycle_consequence(cls, exit_level, derived, "FB_Exit") + "; write " + fix);
        }
      }
    }
  }

  // --- The walk -----------------------------------------------------------------------

  void walk(CXCursor c) {
    const CXCursorKind kind = clang_getCursorKind(c);
    if (clang_isDeclaration(kind) != 0 && !is_user_location(clang_getCursorLocation(c))) return;
    if (is_class_kind(kind) && clang_isCursorDefinition(c) != 0) {
      check_block_class(c);
      check_uninitialised_members(c);
      if (info(c).is_block) block_classes_.push_back(c);
      check_lifecycle_hooks(c);
    }
    if (is_function_kind(kind)) {
      if (clang_isCursorDefinition(c) == 0) return;  // a declaration only: nothing to check
      CXCursor owner = clang_getCursorSemanticParent(c);
      if (!is_class_kind(clang_getCursorKind(owner))) owner = clang_getNullCursor();
      contexts_.push_back(code_context{c, owner, variables_of(c, owner)});
      for (const CXCursor child : children(c)) walk(child);
      contexts_.pop_back();
      return;
    }
    const code_context* context = contexts_.empty() ? nullptr : &contexts_.back();
    if (kind == CXCursor_CallExpr) {
      check_write(c, context);
      note_property_assignment(c, context);
    }
    if (kind == CXCursor_BinaryOperator || kind == CXCursor_CompoundAssignOperator || kind == CXCursor_UnaryOperator) {
      check_builtin_write(c, context);
    }
    if (kind == CXCursor_MemberRefExpr) {
      check_shadowed(c, context);
      note_lifecycle_call(c, context);
    }
    if (kind == CXCursor_VarDecl && loop_variables_.count(clang_hashCursor(c)) == 0)
      check_uninitialised_local(c, context);
    if (kind == CXCursor_LambdaExpr && takes_args(c)) {  // a FUNCTION: [](args<Vars> in) { ... }
      ++pou_code_depth_;
      for (const CXCursor child : children(c)) walk(child);
      --pou_code_depth_;
      return;
    }
    if (kind == CXCursor_CXXForRangeStmt) {  // `for (E e : a)`: the loop variable is initialised by the loop
      for (const CXCursor child : children(c)) {
        if (clang_getCursorKind(child) == CXCursor_VarDecl) loop_variables_.insert(clang_hashCursor(child));
      }
    }
    for (const CXCursor child : children(c)) walk(child);
  }

  CXTranslationUnit unit_;
  std::string library_dir_;
  std::map<CXFile, bool> user_files_;
  std::map<std::string, class_info> classes_;
  std::vector<code_context> contexts_;
  std::set<unsigned> loop_variables_;
  std::vector<CXCursor> block_classes_;                // every block class the user defines (check 6)
  std::vector<lifecycle_call> lifecycle_calls_;        // check 6, matched at the end
  std::map<unsigned, std::string> property_assigned_;  // a property's member expression: the operator assigning it
  int pou_code_depth_ = 0;                             // inside a lambda that takes args<Vars>
  std::vector<finding> findings_;
};

}  // namespace

std::vector<finding> check_translation_unit(CXTranslationUnit unit) { return checker(unit).run(); }

}  // namespace iecoop_check
