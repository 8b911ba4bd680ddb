// iecoop-check: small helpers over libclang's C API (clang-c/Index.h): strings, children,
// types, names and locations of cursors.
#pragma once

#include <clang-c/Index.h>

#include <string>
#include <vector>

namespace iecoop_check {

/// A libclang string as a std::string (and disposed of).
inline std::string text(CXString s) {
  const char* chars = clang_getCString(s);
  std::string result = chars != nullptr ? chars : "";
  clang_disposeString(s);
  return result;
}

inline std::string spelling(CXCursor c) { return text(clang_getCursorSpelling(c)); }
inline std::string usr(CXCursor c) { return text(clang_getCursorUSR(c)); }
inline bool is_null(CXCursor c) { return clang_Cursor_isNull(c) != 0; }

/// The direct children of a cursor, in source order.
inline std::vector<CXCursor> children(CXCursor c) {
  std::vector<CXCursor> result;
  clang_visitChildren(
      c,
      [](CXCursor child, CXCursor, CXClientData data) {
        static_cast<std::vector<CXCursor>*>(data)->push_back(child);
        return CXChildVisit_Continue;
      },
      &result);
  return result;
}

inline bool is_class_kind(CXCursorKind kind) {
  return kind == CXCursor_StructDecl || kind == CXCursor_ClassDecl || kind == CXCursor_ClassTemplate ||
         kind == CXCursor_ClassTemplatePartialSpecialization;
}

inline bool is_function_kind(CXCursorKind kind) {
  return kind == CXCursor_FunctionDecl || kind == CXCursor_CXXMethod || kind == CXCursor_Constructor ||
         kind == CXCursor_Destructor || kind == CXCursor_ConversionFunction || kind == CXCursor_FunctionTemplate;
}

/// The type without references, canonical (no typedefs, no `var<T>` alias). Its
/// declaration and template arguments do not depend on cv-qualifiers.
inline CXType bare_type(CXType t) {
  t = clang_getCanonicalType(t);
  if (t.kind == CXType_LValueReference || t.kind == CXType_RValueReference) {
    t = clang_getCanonicalType(clang_getPointeeType(t));
  }
  return t;
}

/// The class a type names: its definition where there is one. A null cursor for other types.
inline CXCursor class_of(CXType t) {
  const CXCursor declaration = clang_getTypeDeclaration(bare_type(t));
  if (is_null(declaration) || !is_class_kind(clang_getCursorKind(declaration))) return clang_getNullCursor();
  const CXCursor definition = clang_getCursorDefinition(declaration);
  return is_null(definition) ? declaration : definition;
}

/// Where libclang shows a class's members and bases: the class itself, or, for an implicit
/// instantiation of a class template (whose members libclang does not visit), the template.
inline CXCursor members_of(CXCursor cls) {
  const CXCursor from = clang_getSpecializedCursorTemplate(cls);
  if (!is_null(from) && clang_getCursorKind(cls) != CXCursor_ClassTemplatePartialSpecialization &&
      children(cls).empty()) {
    const CXCursor definition = clang_getCursorDefinition(from);
    return is_null(definition) ? from : definition;
  }
  return cls;
}

/// Whether a declaration is iecoop's own: declared in namespace iecoop (or one inside it).
inline bool in_namespace_iecoop(CXCursor c) {
  std::string outermost;
  for (CXCursor p = clang_getCursorSemanticParent(c); !is_null(p) && clang_getCursorKind(p) != CXCursor_TranslationUnit;
       p = clang_getCursorSemanticParent(p)) {
    if (clang_getCursorKind(p) == CXCursor_Namespace) outermost = spelling(p);
  }
  return outermost == "iecoop";
}

/// iecoop's class (template) `name` or a specialization of it, e.g. is_iecoop_class(c, "local").
inline bool is_iecoop_class(CXCursor c, const char* name) {
  return !is_null(c) && is_class_kind(clang_getCursorKind(c)) && spelling(c) == name && in_namespace_iecoop(c);
}

/// The type of the template argument `index` of a class template specialization type.
inline CXType template_argument(CXType t, unsigned index) {
  t = bare_type(t);
  const int count = clang_Type_getNumTemplateArguments(t);
  if (count < 0 || index >= static_cast<unsigned>(count)) return CXType{CXType_Invalid, {nullptr, nullptr}};
  return clang_Type_getTemplateArgumentAsType(t, index);
}

}  // namespace iecoop_check
