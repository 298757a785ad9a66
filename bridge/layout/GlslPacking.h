// The std140 and std430 packing rules of OpenGL 4.5 (§7.6.2.2, "Standard
// Uniform Block Layout"), evaluated at compile time over a GPU struct's
// member list, and the macro that makes a struct of bridge/layout/GpuLayouts.h
// from its list: the C++ struct, and a static_assert per member that it
// sits at the offset, has the size and the scalar type the rules give its
// GLSL declaration. The same list becomes the GLSL declaration itself
// (gl/ShaderLibrary.cpp), so the two sides cannot drift.
//
// A list entry is X(C++ type, C++ name, GLSL type, GLSL name, GLSL array
// length or 0). The C++ type may differ from the GLSL one where the bytes
// agree (a glm::uvec4 over GLSL's uint[4], which std430 packs at 4-byte
// alignment as GLM's unaligned vectors are); the checks hold it to the
// GLSL declaration's offset, size and scalar type.
#pragma once

#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string_view>
#include <type_traits>

namespace eikon::layout {

enum class Packing { kStd140, kStd430 };

// A GLSL type's base alignment and size; a struct's by the packing it is
// declared for (a struct member is laid out by its own packing: nest only
// structs of the packing of the block that holds them).
struct GlslType {
    std::size_t alignment = 0;
    std::size_t size = 0;
};

// The C++ type each GLSL type name of a list stands for.
namespace glsl {
using uint = std::uint32_t;
using vec4 = glm::vec4;
using ivec4 = glm::ivec4;
using uvec4 = glm::uvec4;
}  // namespace glsl

template <class T>
inline constexpr GlslType glslTypeOf{};  // 0: not a GLSL type; structs get theirs from EIKON_LAYOUT_STRUCT
template <>
inline constexpr GlslType glslTypeOf<glsl::uint> = {4, 4};
template <>
inline constexpr GlslType glslTypeOf<glsl::vec4> = {16, 16};
template <>
inline constexpr GlslType glslTypeOf<glsl::ivec4> = {16, 16};
template <>
inline constexpr GlslType glslTypeOf<glsl::uvec4> = {16, 16};

// The scalar a type is made of: a vector's component, an array's element's,
// a struct itself.
template <class T>
struct ScalarOf {
    using type = T;
};
template <glm::length_t L, class T, glm::qualifier Q>
struct ScalarOf<glm::vec<L, T, Q>> {
    using type = T;
};
template <class T, std::size_t N>
struct ScalarOf<T[N]> : ScalarOf<T> {};
template <class T>
using ScalarOfT = typename ScalarOf<T>::type;

struct GlslMember {
    std::string_view name;
    std::string_view typeName;  // as GLSL spells it
    GlslType type;
    std::size_t count;  // array length; 0: not an array
};

constexpr std::size_t roundUp(std::size_t n, std::size_t multiple) { return (n + multiple - 1) / multiple * multiple; }

// Rules 1–4 and 9 (std140) and their std430 form: an array's base alignment
// and stride are its element's, rounded up to a vec4's under std140.
constexpr std::size_t memberAlignment(Packing packing, const GlslMember& member) {
    if (member.type.alignment == 0) throw std::logic_error("a member's GLSL type has no layout");
    return packing == Packing::kStd140 && member.count > 0 ? roundUp(member.type.alignment, 16) : member.type.alignment;
}

constexpr std::size_t memberBytes(Packing packing, const GlslMember& member) {
    if (member.count == 0) return member.type.size;
    return member.count * roundUp(member.type.size, memberAlignment(packing, member));
}

// The offset of the member named `name`: each member starts at the next
// multiple of its base alignment after the one before it.
constexpr std::size_t glslOffset(Packing packing, std::span<const GlslMember> members, std::string_view name) {
    std::size_t offset = 0;
    for (const GlslMember& member : members) {
        offset = roundUp(offset, memberAlignment(packing, member));
        if (member.name == name) return offset;
        offset += memberBytes(packing, member);
    }
    throw std::logic_error("no such member");
}

constexpr std::size_t glslBytes(Packing packing, std::span<const GlslMember> members, std::string_view name) {
    for (const GlslMember& member : members)
        if (member.name == name) return memberBytes(packing, member);
    throw std::logic_error("no such member");
}

// Rule 9: a struct aligns to its largest member (rounded up to a vec4's
// under std140) and its size is padded to that alignment.
constexpr GlslType glslStruct(Packing packing, std::span<const GlslMember> members) {
    std::size_t alignment = packing == Packing::kStd140 ? 16 : 1;
    std::size_t end = 0;
    for (const GlslMember& member : members) {
        const std::size_t memberAlign = memberAlignment(packing, member);
        alignment = memberAlign > alignment ? memberAlign : alignment;
        end = roundUp(end, memberAlign) + memberBytes(packing, member);
    }
    return {alignment, roundUp(end, alignment)};
}

}  // namespace eikon::layout

#define EIKON_LAYOUT_CPP_MEMBER(cppType, cppName, glslType, glslName, count) cppType cppName;
#define EIKON_LAYOUT_GLSL_MEMBER(cppType, cppName, glslType, glslName, count) \
    ::eikon::layout::GlslMember{#glslName, #glslType, ::eikon::layout::glslTypeOf<::eikon::layout::glsl::glslType>, count},
#define EIKON_LAYOUT_CHECK_MEMBER(cppType, cppName, glslType, glslName, count)                                    \
    static_assert(offsetof(Checked, cppName) == ::eikon::layout::glslOffset(kPacking, kMembers, #glslName),       \
                  #cppName " is not at the offset the packing rules give GLSL's " #glslName);                    \
    static_assert(sizeof(cppType) == ::eikon::layout::glslBytes(kPacking, kMembers, #glslName),                   \
                  #cppName " and GLSL's " #glslName " differ in size");                                           \
    static_assert(std::is_same_v<::eikon::layout::ScalarOfT<cppType>,                                             \
                                 ::eikon::layout::ScalarOfT<::eikon::layout::glsl::glslType>>,                    \
                  #cppName " and GLSL's " #glslName " differ in scalar type");

// The struct `Name` from its member list LIST, laid out by `packing` (a
// Packing enumerator), with its GLSL type and its checks; in namespace
// eikon::layout.
#define EIKON_LAYOUT_STRUCT(Name, LIST, packing)                                                             \
    struct Name {                                                                                            \
        LIST(EIKON_LAYOUT_CPP_MEMBER)                                                                        \
    };                                                                                                       \
    inline constexpr GlslMember Name##Members[] = {LIST(EIKON_LAYOUT_GLSL_MEMBER)};                          \
    template <>                                                                                              \
    inline constexpr GlslType glslTypeOf<Name> = glslStruct(Packing::packing, Name##Members);                \
    struct Name##Checks {                                                                                    \
        using Checked = Name;                                                                                \
        static constexpr Packing kPacking = Packing::packing;                                                \
        static constexpr std::span<const GlslMember> kMembers = Name##Members;                               \
        LIST(EIKON_LAYOUT_CHECK_MEMBER)                                                                      \
        static_assert(sizeof(Name) == glslTypeOf<Name>.size, #Name " has members its GLSL declaration lacks"); \
    };
