#include "cli/SettingsOptions.h"

#include <stdexcept>

#include "core/SettingsSchema.h"

namespace conescope::cli {

namespace {

// A CLI11 validator from the schema's parser: its std::invalid_argument message (which names what
// is accepted) becomes the parse error.
CLI::Validator schemaValidator(const SettingField& field) {
    return CLI::Validator(
        [&field](std::string& text) -> std::string {
            Settings scratch;
            try {
                parseSetting(field, text, scratch);
                return {};
            } catch (const std::invalid_argument& error) {
                // CLI11 names the option itself.
                const std::string message = error.what(), prefix = "--" + field.flag + ": ";
                return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
            }
        },
        "");
}

std::string joined(const std::vector<std::string>& texts) {
    std::string text;
    for (const std::string& part : texts) text += (text.empty() ? "" : ",") + part;
    return text;
}

void addOptions(CLI::App& command, SettingsOptions& options, bool builderFields) {
    for (const SettingField& field : settingFields()) {
        if (field.builderOption != builderFields) continue;
        const std::string name = "--" + field.flag;
        if (field.kind == SettingKind::Flag) {
            options.options[field.flag] = command.add_flag(name, options.flags[field.flag], settingHelp(field));
            continue;
        }
        CLI::Option* option = command.add_option(name, options.values[field.flag], settingHelp(field));
        option->type_name(field.valueName)->check(schemaValidator(field));
        const std::string defaultText = settingText(field, Settings{});
        if (!defaultText.empty()) option->default_str(defaultText);
        if (field.kind == SettingKind::NameList)
            option->delimiter(',')->allow_extra_args(false);
        else
            option->expected(1)->multi_option_policy(CLI::MultiOptionPolicy::Throw);
        options.options[field.flag] = option;
    }
    for (const SettingField& field : settingFields())
        for (const std::string& excluded : field.excludes)
            if (options.options.count(field.flag) && options.options.count(excluded))
                options.options[field.flag]->excludes(options.options[excluded]);
}

}  // namespace

Settings SettingsOptions::toSettings() const {
    Settings settings;
    for (const SettingField& field : settingFields()) {
        const auto option = options.find(field.flag);
        if (option == options.end() || option->second->count() == 0) continue;
        if (field.kind == SettingKind::Flag)
            parseSetting(field, flags.at(field.flag) ? "true" : "false", settings);
        else
            parseSetting(field, joined(values.at(field.flag)), settings);
    }
    return settings;
}

void addBuilderOptions(CLI::App& command, SettingsOptions& options) { addOptions(command, options, true); }

void addCullingOptions(CLI::App& command, SettingsOptions& options) { addOptions(command, options, false); }

}  // namespace conescope::cli
