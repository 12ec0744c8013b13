//! AccessKit roles as WAI-ARIA roles (the roles egui gives its widgets, and the structure
//! around them); a role with no ARIA twin is left out of the mirror unless it holds text.

use egui::accesskit::Role;

/// The ARIA role of an AccessKit role ("" for none: a generic container or an unknown role).
pub fn aria_role(role: Role) -> &'static str {
    match role {
        Role::Button | Role::DefaultButton => "button",
        Role::CheckBox => "checkbox",
        Role::Switch => "switch",
        Role::RadioButton => "radio",
        Role::RadioGroup => "radiogroup",
        Role::ComboBox | Role::EditableComboBox => "combobox",
        Role::ListBox => "listbox",
        Role::ListBoxOption | Role::MenuListOption => "option",
        Role::Slider => "slider",
        Role::SpinButton => "spinbutton",
        Role::TextInput
        | Role::MultilineTextInput
        | Role::SearchInput
        | Role::NumberInput
        | Role::EmailInput
        | Role::PasswordInput
        | Role::PhoneNumberInput
        | Role::UrlInput => "textbox",
        Role::Link => "link",
        Role::Tab => "tab",
        Role::TabList => "tablist",
        Role::TabPanel => "tabpanel",
        Role::ProgressIndicator => "progressbar",
        Role::Meter => "meter",
        Role::Image => "img",
        Role::Heading => "heading",
        Role::Menu | Role::MenuListPopup => "menu",
        Role::MenuBar => "menubar",
        Role::MenuItem => "menuitem",
        Role::MenuItemCheckBox => "menuitemcheckbox",
        Role::MenuItemRadio => "menuitemradio",
        Role::Tooltip => "tooltip",
        Role::Alert => "alert",
        Role::Dialog | Role::Window => "dialog",
        Role::AlertDialog => "alertdialog",
        Role::Group | Role::Pane => "group",
        Role::ScrollView => "group",
        Role::ScrollBar => "scrollbar",
        Role::Splitter => "separator",
        Role::DisclosureTriangle => "button",
        Role::Grid => "grid",
        Role::Table => "table",
        Role::Row => "row",
        Role::Cell | Role::GridCell => "cell",
        Role::List => "list",
        Role::ListItem => "listitem",
        Role::Status => "status",
        Role::Toolbar => "toolbar",
        Role::Figure => "figure",
        Role::Region => "region",
        _ => "",
    }
}

/// A role that only groups others: mirrored only when it has a name of its own.
pub fn is_container(role: Role) -> bool {
    matches!(
        role,
        Role::GenericContainer
            | Role::Group
            | Role::Pane
            | Role::ScrollView
            | Role::Window
            | Role::Unknown
            | Role::Row
            | Role::Cell
            | Role::GridCell
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_controls_egui_makes_have_their_aria_roles() {
        assert_eq!(aria_role(Role::Slider), "slider");
        assert_eq!(aria_role(Role::Button), "button");
        assert_eq!(aria_role(Role::CheckBox), "checkbox");
        assert_eq!(aria_role(Role::ComboBox), "combobox");
        assert_eq!(aria_role(Role::SpinButton), "spinbutton");
        assert_eq!(aria_role(Role::GenericContainer), "");
        assert!(is_container(Role::GenericContainer));
        assert!(!is_container(Role::Slider));
    }
}
