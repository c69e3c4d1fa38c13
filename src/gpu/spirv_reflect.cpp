#include "gpu/spirv_reflect.h"

#include <algorithm>
#include <unordered_map>

#include "error.h"

namespace vct {
namespace {

// Numbers from the SPIR-V specification (unified 1.6), section 3.
constexpr uint32_t kMagic = 0x07230203u;
constexpr uint32_t kHeaderWords = 5;
enum Op : uint32_t {
    OpName = 5,
    OpMemberName = 6,
    OpEntryPoint = 15,
    OpExecutionMode = 16,
    OpTypeBool = 20,
    OpTypeInt = 21,
    OpTypeFloat = 22,
    OpTypeVector = 23,
    OpTypeMatrix = 24,
    OpTypeImage = 25,
    OpTypeSampler = 26,
    OpTypeSampledImage = 27,
    OpTypeArray = 28,
    OpTypeRuntimeArray = 29,
    OpTypeStruct = 30,
    OpTypePointer = 32,
    OpConstant = 43,
    OpSpecConstant = 50,
    OpVariable = 59,
    OpDecorate = 71,
    OpMemberDecorate = 72,
    OpExecutionModeId = 331,
};
enum Decoration : uint32_t {
    SpecId = 1,
    Block = 2,
    BufferBlock = 3,
    RowMajor = 4,
    ArrayStride = 6,
    MatrixStride = 7,
    Binding = 33,
    DescriptorSet = 34,
    Offset = 35,
};
enum StorageClass : uint32_t { UniformConstant = 0, Uniform = 2, PushConstant = 9, StorageBuffer = 12 };
constexpr uint32_t kDimBuffer = 5, kDimSubpassData = 6;
constexpr uint32_t kLocalSize = 17, kLocalSizeId = 38;  // execution modes
// Execution models 0..5: vertex, tessellation control and evaluation, geometry, fragment, compute.
constexpr VkShaderStageFlagBits kStages[] = {VK_SHADER_STAGE_VERTEX_BIT,
                                             VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT,
                                             VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT,
                                             VK_SHADER_STAGE_GEOMETRY_BIT,
                                             VK_SHADER_STAGE_FRAGMENT_BIT,
                                             VK_SHADER_STAGE_COMPUTE_BIT};
constexpr const char* kStageNames[] = {
    "vertex", "tessellation control", "tessellation evaluation", "geometry", "fragment", "compute"};
// Deeper nesting than this is taken for a type that contains itself (invalid, but it must not overflow the stack).
constexpr int kMaxTypeDepth = 32;

struct MemberLayout {
    uint32_t offset = 0, matrixStride = 0;
    bool rowMajor = false;
};

// One result id: where its defining instruction is (its operands are read from there when needed) and its
// decorations, which come before the types in a module and so are recorded on ids not defined yet.
struct Id {
    uint32_t opcode = 0;  // 0 = not defined (yet)
    const uint32_t* words = nullptr;
    uint32_t wordCount = 0;
    std::optional<uint32_t> set, binding, specId, arrayStride;
    bool block = false, bufferBlock = false;
    std::vector<MemberLayout> memberLayouts;
    std::string name;                      // OpName
    std::vector<std::string> memberNames;  // OpMemberName
};

// A literal string of a SPIR-V instruction: UTF-8, nul-terminated, packed four bytes a word, the
// first byte in the lowest bits. `words` are the instruction's words from the string's first.
std::string literalString(const uint32_t* words, uint32_t count) {
    std::string text;
    for (uint32_t i = 0; i < count; ++i)
        for (int byte = 0; byte < 4; ++byte) {
            const char c = char((words[i] >> (8 * byte)) & 0xffu);
            if (c == '\0') return text;
            text += c;
        }
    return text;
}

std::string stageNames(VkShaderStageFlags stages) {
    std::string names;
    for (size_t i = 0; i < std::size(kStages); ++i)
        if (stages & kStages[i]) names += (names.empty() ? "" : "+") + std::string(kStageNames[i]);
    return names;
}

std::string describe(const ReflectedBinding& b) {
    return std::string(descriptorTypeName(b.type)) + (b.count == 1 ? "" : " array of " + std::to_string(b.count));
}

// Adds `b` to `into`, or ORs its stages into the binding already there, which must be the same descriptor.
void addBinding(std::vector<ReflectedBinding>& into, const ReflectedBinding& b, const std::string& where) {
    auto same = [&](const ReflectedBinding& other) { return other.set == b.set && other.binding == b.binding; };
    auto found = std::find_if(into.begin(), into.end(), same);
    if (found == into.end()) return into.push_back(b);
    if (found->type != b.type || found->count != b.count)
        throw Error(where + ": set " + std::to_string(b.set) + " binding " + std::to_string(b.binding) + " is a " +
                    describe(*found) + " in the " + stageNames(found->stages) + " stage but a " + describe(b) +
                    " in the " + stageNames(b.stages) + " stage");
    found->stages |= b.stages;
}

void sortBindings(std::vector<ReflectedBinding>& bindings) {
    std::sort(bindings.begin(), bindings.end(), [](const ReflectedBinding& a, const ReflectedBinding& b) {
        return a.set != b.set ? a.set < b.set : a.binding < b.binding;
    });
}

struct Module {
    const std::string& name;
    uint32_t bound = 0;
    // A map, not a vector of `bound` ids: optimizers leave bounds far above the ids in use, and the bound
    // of a malformed module could be anything.
    std::unordered_map<uint32_t, Id> ids;

    [[noreturn]] void fail(const std::string& problem) const { throw Error(name + ": " + problem); }

    Id& at(uint32_t id) {
        if (id == 0 || id >= bound) fail("id " + std::to_string(id) + " is out of the bound " + std::to_string(bound));
        return ids[id];
    }
    const Id& defined(uint32_t id) {
        const Id& result = at(id);
        if (result.opcode == 0) fail("id " + std::to_string(id) + " is used but not defined by an instruction read");
        return result;
    }
    // Word `i` of the instruction that defined `id` (word 0 holds the opcode).
    uint32_t operand(const Id& id, uint32_t i) const {
        if (i >= id.wordCount) fail("an instruction of opcode " + std::to_string(id.opcode) + " has too few operands");
        return id.words[i];
    }
    const Id& constant(uint32_t id) {
        const Id& c = defined(id);
        if (c.opcode != OpConstant && c.opcode != OpSpecConstant) fail("id " + std::to_string(id) + " is no constant");
        return c;
    }
    uint32_t value(uint32_t constantId) { return operand(constant(constantId), 3); }

    // Bytes from the start of `typeId` to the end of its last byte, with the layout decorations of the member
    // that holds it (a matrix's stride and order are member decorations).
    uint32_t sizeOf(uint32_t typeId, const MemberLayout& layout, int depth) {
        if (depth > kMaxTypeDepth) fail("a push-constant type nests deeper than " + std::to_string(kMaxTypeDepth));
        const Id& t = defined(typeId);
        switch (t.opcode) {
            case OpTypeInt:
            case OpTypeFloat: return operand(t, 2) / 8;
            case OpTypeVector: return operand(t, 3) * sizeOf(operand(t, 2), layout, depth + 1);
            case OpTypeMatrix:  // column-major: columns × stride; row-major: rows (the column's components) × stride
                if (layout.matrixStride == 0) fail("a push-constant matrix has no MatrixStride decoration");
                return (layout.rowMajor ? operand(defined(operand(t, 2)), 3) : operand(t, 3)) * layout.matrixStride;
            case OpTypeArray:
                if (!t.arrayStride) fail("a push-constant array has no ArrayStride decoration");
                return value(operand(t, 3)) * *t.arrayStride;
            case OpTypeStruct: {
                uint32_t end = 0;
                for (uint32_t i = 0; i + 2 < t.wordCount; ++i) {
                    const MemberLayout member = i < t.memberLayouts.size() ? t.memberLayouts[i] : MemberLayout{};
                    end = std::max(end, member.offset + sizeOf(t.words[i + 2], member, depth + 1));
                }
                return end;
            }
            default: fail("push constants hold a type of opcode " + std::to_string(t.opcode) + ", which has no size");
        }
    }

    VkDescriptorType descriptorType(const Id& t, uint32_t storageClass, const std::string& where) {
        switch (t.opcode) {
            case OpTypeStruct:
                if (storageClass == Uniform && t.block) return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
                if ((storageClass == Uniform && t.bufferBlock) || (storageClass == StorageBuffer && t.block))
                    return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                fail(where + " is a struct that is neither a Block nor a BufferBlock");
            case OpTypeSampledImage: {
                const Id& image = defined(operand(t, 2));
                return operand(image, 3) == kDimBuffer ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                                                       : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
            }
            case OpTypeImage: {  // operands: sampled type, Dim, Depth, Arrayed, MS, Sampled, format
                const uint32_t dim = operand(t, 3), sampled = operand(t, 7);
                if (dim == kDimSubpassData) return VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT;
                if (sampled == 1)
                    return dim == kDimBuffer ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                                             : VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
                if (sampled == 2)
                    return dim == kDimBuffer ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER
                                             : VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
                fail(where + " is an image that is neither sampled nor storage (Sampled " + std::to_string(sampled) +
                     ")");
            }
            case OpTypeSampler: return VK_DESCRIPTOR_TYPE_SAMPLER;
            case OpTypeRuntimeArray: fail(where + " is a runtime-sized array, which is not supported");
            default: fail(where + " has a descriptor type of opcode " + std::to_string(t.opcode) + ", not supported");
        }
    }
};

}  // namespace

const char* descriptorTypeName(VkDescriptorType type) {
    switch (type) {
        case VK_DESCRIPTOR_TYPE_SAMPLER: return "sampler";
        case VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER: return "combined image sampler";
        case VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE: return "sampled image";
        case VK_DESCRIPTOR_TYPE_STORAGE_IMAGE: return "storage image";
        case VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER: return "uniform texel buffer";
        case VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER: return "storage texel buffer";
        case VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER: return "uniform buffer";
        case VK_DESCRIPTOR_TYPE_STORAGE_BUFFER: return "storage buffer";
        case VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT: return "input attachment";
        default: return "descriptor of unknown type";
    }
}

ShaderReflection reflectShader(const std::vector<uint32_t>& words, const std::string& name) {
    if (words.size() < kHeaderWords)
        throw Error(name + ": too short for SPIR-V (" + std::to_string(words.size()) + " words; the header is 5)");
    if (words[0] != kMagic) throw Error(name + ": not SPIR-V (wrong magic number)");
    Module module{name, words[3], {}};
    ShaderReflection result;
    uint32_t localSizeIds[3] = {};
    std::vector<uint32_t> variables;
    for (size_t at = kHeaderWords; at < words.size();) {
        const uint32_t wordCount = words[at] >> 16, opcode = words[at] & 0xffffu;
        auto bad = [&](const std::string& problem) {
            module.fail("the instruction at word " + std::to_string(at) + " (opcode " + std::to_string(opcode) + ") " +
                        problem);
        };
        if (wordCount == 0) bad("has word count 0");
        if (at + wordCount > words.size()) bad("is truncated: the module ends inside it");
        auto arg = [&](uint32_t i) {
            if (i >= wordCount) bad("has too few operands");
            return words[at + i];
        };
        auto define = [&](uint32_t resultWord) {
            Id& id = module.at(arg(resultWord));
            id.opcode = opcode;
            id.words = &words[at];
            id.wordCount = wordCount;
        };
        switch (opcode) {
            case OpName:
                if (wordCount < 3) bad("has too few operands");
                module.at(arg(1)).name = literalString(&words[at + 2], wordCount - 2);
                break;
            case OpMemberName: {
                if (wordCount < 4) bad("has too few operands");
                Id& target = module.at(arg(1));
                const uint32_t member = arg(2);
                if (member >= words.size()) bad("names member " + std::to_string(member) + " of a struct");
                if (member >= target.memberNames.size()) target.memberNames.resize(member + 1);
                target.memberNames[member] = literalString(&words[at + 3], wordCount - 3);
                break;
            }
            case OpEntryPoint:
                if (arg(1) >= std::size(kStages))
                    bad("has execution model " + std::to_string(arg(1)) + ", not supported");
                result.stage |= kStages[arg(1)];
                break;
            case OpExecutionMode:
                if (arg(2) == kLocalSize)
                    for (uint32_t axis = 0; axis < 3; ++axis) result.localSize[axis] = arg(3 + axis);
                break;
            case OpExecutionModeId:  // glslang writes this for SPIR-V 1.6: the sizes are constants, defined later
                if (arg(2) == kLocalSizeId)
                    for (uint32_t axis = 0; axis < 3; ++axis) localSizeIds[axis] = arg(3 + axis);
                break;
            case OpDecorate: {
                Id& target = module.at(arg(1));
                switch (arg(2)) {
                    case DescriptorSet: target.set = arg(3); break;
                    case Binding: target.binding = arg(3); break;
                    case SpecId: target.specId = arg(3); break;
                    case ArrayStride: target.arrayStride = arg(3); break;
                    case Block: target.block = true; break;
                    case BufferBlock: target.bufferBlock = true; break;
                }
                break;
            }
            case OpMemberDecorate: {
                Id& target = module.at(arg(1));
                const uint32_t member = arg(2);
                if (member >= words.size()) bad("decorates member " + std::to_string(member) + " of a struct");
                if (member >= target.memberLayouts.size()) target.memberLayouts.resize(member + 1);
                if (arg(3) == Offset) target.memberLayouts[member].offset = arg(4);
                if (arg(3) == MatrixStride) target.memberLayouts[member].matrixStride = arg(4);
                if (arg(3) == RowMajor) target.memberLayouts[member].rowMajor = true;
                break;
            }
            case OpTypeBool:
            case OpTypeInt:
            case OpTypeFloat:
            case OpTypeVector:
            case OpTypeMatrix:
            case OpTypeImage:
            case OpTypeSampler:
            case OpTypeSampledImage:
            case OpTypeArray:
            case OpTypeRuntimeArray:
            case OpTypeStruct:
            case OpTypePointer: define(1); break;
            case OpVariable: variables.push_back(arg(2)); [[fallthrough]];
            case OpConstant:
            case OpSpecConstant: define(2); break;
        }
        at += wordCount;
    }
    if (result.stage == 0) module.fail("the module has no entry point");
    // Ids in order, so that of two laid-out types of one name (a struct in a std140 block and in a
    // std430 one) the first is kept, whatever the map's order.
    std::vector<uint32_t> structIds;
    for (const auto& [number, id] : module.ids)
        if (id.opcode == OpTypeStruct && !id.name.empty() && !id.memberLayouts.empty()) structIds.push_back(number);
    std::sort(structIds.begin(), structIds.end());
    for (uint32_t number : structIds) {
        const Id& id = module.ids[number];
        if (result.structLayouts.count(id.name)) continue;
        std::vector<ReflectedMember>& members = result.structLayouts[id.name];
        for (uint32_t i = 0; i + 2 < id.wordCount; ++i)
            members.push_back({i < id.memberNames.size() ? id.memberNames[i] : std::string(),
                               i < id.memberLayouts.size() ? id.memberLayouts[i].offset : 0u});
    }
    for (int axis = 0; axis < 3; ++axis)
        if (localSizeIds[axis] != 0) result.localSize[axis] = module.value(localSizeIds[axis]);

    for (uint32_t variableId : variables) {
        const Id& variable = module.ids[variableId];
        const uint32_t storage = module.operand(variable, 3);
        const Id& pointer = module.defined(module.operand(variable, 1));
        if (pointer.opcode != OpTypePointer) module.fail("variable " + std::to_string(variableId) + " is no pointer");
        const uint32_t pointee = module.operand(pointer, 3);
        if (storage == PushConstant)
            result.pushConstantBytes = std::max(result.pushConstantBytes, module.sizeOf(pointee, {}, 0));
        if (storage != UniformConstant && storage != Uniform && storage != StorageBuffer) continue;
        if (!variable.binding) module.fail("the descriptor variable " + std::to_string(variableId) + " has no Binding");
        ReflectedBinding b;
        b.set = variable.set.value_or(0);
        b.binding = *variable.binding;
        b.stages = result.stage;
        const std::string where = "set " + std::to_string(b.set) + " binding " + std::to_string(b.binding);
        // An array of descriptors is one binding of `count` descriptors ([2][3] counts 6).
        const Id* type = &module.defined(pointee);
        for (int depth = 0; type->opcode == OpTypeArray; ++depth) {
            if (depth > kMaxTypeDepth) module.fail(where + " nests arrays too deep");
            const Id& length = module.constant(module.operand(*type, 3));
            b.count *= module.operand(length, 3);
            if (length.opcode == OpSpecConstant) b.countSpecId = length.specId;
            type = &module.defined(module.operand(*type, 2));
        }
        b.type = module.descriptorType(*type, storage, where);
        addBinding(result.bindings, b, name);
    }
    sortBindings(result.bindings);
    return result;
}

ShaderReflection mergeStages(const std::vector<ShaderReflection>& stages, const std::string& pipelineName) {
    ShaderReflection merged;
    for (const ShaderReflection& stage : stages) {
        merged.stage |= stage.stage;
        merged.pushConstantBytes = std::max(merged.pushConstantBytes, stage.pushConstantBytes);
        if (stage.stage & VK_SHADER_STAGE_COMPUTE_BIT) std::copy_n(stage.localSize, 3, merged.localSize);
        for (const ReflectedBinding& b : stage.bindings) addBinding(merged.bindings, b, pipelineName);
    }
    sortBindings(merged.bindings);
    return merged;
}

}  // namespace vct
