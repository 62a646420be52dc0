// Run-time selection: a family of models, each registered under a name by an explicit
// registration function (no static initialisers), and created from the word a case gives.
// An unknown word is a FatalError naming the family, the word, its file and line, and the
// sorted valid names; registering a name twice is an error too.
#pragma once

#include "core/FatalError.hpp"
#include "core/Spelling.hpp"

#include <concepts>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace sph {

// What `-listModels` prints about one coefficient.
struct CoefficientDoc {
    std::string keyword;
    std::string defaultValue;  // empty: required
    std::string meaning;
};

struct ModelDoc {
    std::string summary;
    std::string reference;
    std::vector<CoefficientDoc> coefficients;
};

template <class Product, class... Args>
class Registry {
public:
    using Factory = std::function<Product(Args...)>;

    explicit Registry(std::string family) : family_(std::move(family)) {}

    void add(const std::string& name, ModelDoc doc, Factory factory) {
        if (entries_.count(name)) throw FatalError("error: " + family_ + " '" + name + "' is registered twice");
        entries_.emplace(name, Item{std::move(doc), std::move(factory)});
    }

    // `where` is the location of the word in the case, for the error message.
    Product create(const std::string& name, const SourceLocation& where, Args... args) const {
        auto it = entries_.find(name);
        if (it == entries_.end()) throw FatalError(where, unknownMessage(name));
        return it->second.factory(std::forward<Args>(args)...);
    }

    std::string unknownMessage(const std::string& name) const {
        std::string message = "unknown " + family_ + " '" + name + "'; valid " + family_ + " names are:";
        for (const auto& [valid, item] : entries_) message += "\n    " + valid;
        const std::string nearest = nearestSpelling(name, names());
        return nearest.empty() ? message : message + "\n(did you mean '" + nearest + "'?)";
    }

    const std::string& family() const { return family_; }
    std::vector<std::string> names() const {
        std::vector<std::string> result;
        for (const auto& [name, item] : entries_) result.push_back(name);
        return result;  // std::map keeps them sorted
    }
    const ModelDoc& doc(const std::string& name) const { return entries_.at(name).doc; }

private:
    struct Item {
        ModelDoc doc;
        Factory factory;
    };
    std::string family_;
    std::map<std::string, Item> entries_;
};

// A model of a variant family (equations of state, viscosities, density diffusions) declares
// itself in its own header: its name, its documentation, its factory from the family's
// arguments and its line in the run log. The family's registry then registers every
// alternative of its variant (registerEach), and its run-log line is the model's (describeModel).
template <class Model, class... Args>
concept SelfDeclaredModel = requires(const Model model, Args... args) {
    { Model::name } -> std::convertible_to<std::string_view>;
    { Model::documentation() } -> std::same_as<ModelDoc>;
    { Model::create(args...) } -> std::same_as<Model>;
    { model.describe() } -> std::same_as<std::string>;
};

template <class... Models, class... Args>
requires(SelfDeclaredModel<Models, Args...>&&...) void registerEach(Registry<std::variant<Models...>, Args...>& registry) {
    (registry.add(std::string(Models::name), Models::documentation(), [](Args... args) { return std::variant<Models...>{Models::create(args...)}; }),
     ...);
}

template <class... Models>
std::string describeModel(const std::variant<Models...>& selected) {
    return std::visit([](const auto& model) { return model.describe(); }, selected);
}

}  // namespace sph
