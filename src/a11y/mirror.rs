//! egui's accessibility tree, read as the list of HTML elements that stand for
//! it in the page.
//!
//! egui describes every widget it draws in an AccessKit tree (role, name,
//! value, range, bounds). eframe's web backend does not hand that tree to the
//! browser, so a screen reader would see one canvas. [`Mirror::from_update`]
//! turns one frame's tree into [`Item`]s in reading order: each control with
//! the HTML element that means the same to assistive technology ([`Kind::tag`]),
//! each window or panel as a named group around its controls. The browser side
//! (`web/a11y_dom.rs`) keeps those elements in the page and turns what a
//! screen reader does to them back into AccessKit action requests.
//!
//! This part is pure: it is tested natively against the real panels.

use std::collections::HashMap;

use eframe::egui::accesskit::{Node, NodeId, Role, Toggled, TreeUpdate};

/// What an element is, with the state assistive technology reads from it.
#[derive(Clone, Debug, PartialEq)]
pub enum Kind {
    /// A push button. `pressed`: for a button that stays down (a selected
    /// tab, a toggle), whether it is.
    Button {
        pressed: Option<bool>,
    },
    /// A button that opens and closes a section (a collapsing header).
    Disclosure {
        expanded: bool,
    },
    CheckBox {
        checked: Option<bool>,
    },
    Radio {
        checked: bool,
    },
    /// A slider or a number to drag: `text` is the value as shown, when it
    /// says more than the number.
    Slider {
        value: f64,
        min: f64,
        max: f64,
        step: Option<f64>,
        text: Option<String>,
    },
    /// A number field without a range of its own (egui's `DragValue`).
    Number {
        value: f64,
        min: Option<f64>,
        max: Option<f64>,
        step: Option<f64>,
    },
    TextInput {
        value: String,
        multiline: bool,
        placeholder: Option<String>,
    },
    /// A drop-down: `value` is the choice shown.
    ComboBox {
        value: String,
        expanded: bool,
    },
    Link,
    /// A list of options (an open drop-down) and one option in it.
    ListBox,
    ListOption {
        selected: bool,
    },
    Progress {
        value: Option<f64>,
    },
    /// Words on screen.
    Text,
    /// A window, panel or other named group of controls.
    Group {
        window: bool,
    },
}

impl Kind {
    /// The HTML element and, where the element does not say it itself, the
    /// ARIA role that stand for this kind.
    pub fn tag(&self) -> (&'static str, Option<&'static str>) {
        match self {
            Kind::Button { .. } | Kind::Disclosure { .. } | Kind::ComboBox { .. } => {
                ("button", None)
            }
            Kind::CheckBox { .. } | Kind::Radio { .. } | Kind::Slider { .. } => ("input", None),
            Kind::Number { .. } => ("input", None),
            Kind::TextInput {
                multiline: true, ..
            } => ("textarea", None),
            Kind::TextInput { .. } => ("input", None),
            Kind::Link => ("a", None),
            Kind::ListBox => ("div", Some("listbox")),
            Kind::ListOption { .. } => ("div", Some("option")),
            Kind::Progress { .. } => ("div", Some("progressbar")),
            Kind::Text => ("p", None),
            Kind::Group { window: true } => ("section", Some("dialog")),
            Kind::Group { window: false } => ("section", Some("group")),
        }
    }

    /// The `type` of an `input` element.
    pub fn input_type(&self) -> Option<&'static str> {
        match self {
            Kind::CheckBox { .. } => Some("checkbox"),
            Kind::Radio { .. } => Some("radio"),
            Kind::Slider { .. } => Some("range"),
            Kind::Number { .. } => Some("number"),
            Kind::TextInput {
                multiline: false, ..
            } => Some("text"),
            _ => None,
        }
    }

    /// Whether this kind holds other items.
    pub fn is_group(&self) -> bool {
        matches!(self, Kind::Group { .. } | Kind::ListBox)
    }

    /// Whether a keyboard or screen reader can move to it and act on it.
    pub fn is_control(&self) -> bool {
        !matches!(
            self,
            Kind::Text | Kind::Group { .. } | Kind::ListBox | Kind::Progress { .. }
        )
    }
}

/// One element of the mirror.
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    /// egui's AccessKit node id: action requests name it.
    pub id: u64,
    /// The group this item sits in (`None`: the top level).
    pub parent: Option<u64>,
    pub kind: Kind,
    /// The accessible name (for [`Kind::Text`], the words).
    pub name: String,
    /// Longer help, read after the name (a setting's hover text).
    pub description: Option<String>,
    /// Where egui drew it, in points: `[left, top, right, bottom]`.
    pub bounds: Option<[f32; 4]>,
    pub disabled: bool,
}

/// One frame of egui's accessibility tree as the page's elements.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mirror {
    /// In reading order (depth first, as egui laid them out); a group comes
    /// before the items inside it.
    pub items: Vec<Item>,
    /// The item egui's keyboard focus is on, if any.
    pub focus: Option<u64>,
}

impl Mirror {
    /// Reads one frame's tree. egui sends the whole tree every frame it is
    /// asked for one, so one update is enough.
    pub fn from_update(update: &TreeUpdate) -> Mirror {
        let nodes: HashMap<NodeId, &Node> = update.nodes.iter().map(|(id, n)| (*id, n)).collect();
        let Some(root) = update.tree.as_ref().map(|t| t.root) else {
            return Mirror::default();
        };
        let mut mirror = Mirror::default();
        let mut stack: Vec<(NodeId, Option<u64>)> = vec![(root, None)];
        while let Some((id, parent)) = stack.pop() {
            let Some(node) = nodes.get(&id) else {
                continue;
            };
            if node.is_hidden() {
                continue;
            }
            // The root is the page itself: its children are the top level.
            let item = if id == root {
                None
            } else {
                item_of(id, node, parent).map(|mut item| {
                    if item.name.is_empty() {
                        item.name = labelled_by(node, &nodes);
                    }
                    // egui does not say a drop-down is open; its list shows it.
                    if let Kind::ComboBox { expanded, .. } = &mut item.kind {
                        *expanded |= node
                            .children()
                            .iter()
                            .any(|c| nodes.get(c).is_some_and(|n| n.role() == Role::ListBox));
                    }
                    item
                })
            };
            // Children of a control are its own parts (a text field's runs of
            // text): the control speaks for them. But an open drop-down's
            // list is there to be chosen from: it follows the drop-down.
            let (descend, children_parent) = match &item {
                Some(item) if item.kind.is_group() => (true, Some(item.id)),
                Some(item) if matches!(item.kind, Kind::ComboBox { .. }) => (true, parent),
                Some(_) => (false, parent),
                None => (true, parent),
            };
            if let Some(item) = item {
                mirror.items.push(item);
            }
            if descend {
                for child in node.children().iter().rev() {
                    stack.push((*child, children_parent));
                }
            }
        }
        let focus = update.focus.0;
        if mirror.items.iter().any(|i| i.id == focus) {
            mirror.focus = Some(focus);
        }
        drop_slider_value_boxes(&mut mirror.items);
        drop_repeated_labels(&mut mirror.items);
        drop_empty_groups(&mut mirror.items);
        mirror
    }

    /// The items a keyboard or screen reader acts on.
    pub fn controls(&self) -> impl Iterator<Item = &Item> {
        self.items.iter().filter(|i| i.kind.is_control())
    }

    /// The first control named `name`.
    pub fn control(&self, name: &str) -> Option<&Item> {
        self.controls().find(|i| i.name == name)
    }
}

/// The words of the nodes that `node` is labelled by (a visible label next
/// to it), joined.
fn labelled_by(node: &Node, nodes: &HashMap<NodeId, &Node>) -> String {
    node.labelled_by()
        .iter()
        .filter_map(|id| nodes.get(id))
        .filter_map(|label| label.label().or_else(|| label.value()))
        .collect::<Vec<_>>()
        .join(" ")
}

/// The item for one node, or `None` for a node that only arranges others
/// (its children are read in its place) or that a screen reader need not see.
fn item_of(id: NodeId, node: &Node, parent: Option<u64>) -> Option<Item> {
    let name = node
        .label()
        .map(str::to_owned)
        .or_else(|| {
            node.value()
                .filter(|_| node.role() == Role::Label)
                .map(str::to_owned)
        })
        .unwrap_or_default();
    let value = node.value().unwrap_or_default().to_owned();
    let kind = match node.role() {
        Role::Button | Role::DefaultButton | Role::Tab | Role::MenuItem => Kind::Button {
            pressed: match node.toggled() {
                Some(Toggled::True) => Some(true),
                Some(_) => Some(false),
                None => node.is_selected(),
            },
        },
        Role::DisclosureTriangle => Kind::Disclosure {
            expanded: node.is_expanded().unwrap_or(false),
        },
        Role::CheckBox | Role::Switch => Kind::CheckBox {
            checked: match node.toggled() {
                Some(Toggled::True) => Some(true),
                Some(Toggled::False) | None => Some(false),
                Some(Toggled::Mixed) => None,
            },
        },
        Role::RadioButton => Kind::Radio {
            checked: node.toggled() == Some(Toggled::True),
        },
        Role::Slider => Kind::Slider {
            value: node.numeric_value().unwrap_or(0.0),
            min: node.min_numeric_value().unwrap_or(0.0),
            max: node.max_numeric_value().unwrap_or(1.0),
            step: node.numeric_value_step(),
            text: node.value().map(str::to_owned),
        },
        Role::SpinButton => Kind::Number {
            value: node.numeric_value().unwrap_or(0.0),
            min: node.min_numeric_value(),
            max: node.max_numeric_value(),
            step: node.numeric_value_step(),
        },
        Role::TextInput | Role::SearchInput | Role::MultilineTextInput => Kind::TextInput {
            value,
            multiline: node.role() == Role::MultilineTextInput,
            placeholder: node.placeholder().map(str::to_owned),
        },
        Role::ComboBox => Kind::ComboBox {
            value,
            expanded: node.is_expanded().unwrap_or(false),
        },
        Role::Link => Kind::Link,
        Role::ListBox => Kind::ListBox,
        Role::ListBoxOption | Role::MenuListOption => Kind::ListOption {
            selected: node.is_selected().unwrap_or(false),
        },
        Role::ProgressIndicator => Kind::Progress {
            value: node.numeric_value(),
        },
        Role::Label | Role::Heading | Role::Paragraph => {
            if name.trim().is_empty() {
                return None;
            }
            Kind::Text
        }
        Role::Window | Role::Dialog => Kind::Group { window: true },
        Role::Pane | Role::Group | Role::Region => Kind::Group { window: false },
        // Containers that only lay out their children, and the parts of
        // widgets (scroll bars, text runs, tooltips) a screen reader reads
        // through the widget itself.
        _ => {
            // A container egui named is a group worth announcing.
            if node.role() == Role::GenericContainer && !name.is_empty() {
                Kind::Group { window: false }
            } else {
                return None;
            }
        }
    };
    let bounds = node
        .bounds()
        .map(|r| [r.x0 as f32, r.y0 as f32, r.x1 as f32, r.y1 as f32]);
    Some(Item {
        id: id.0,
        parent,
        kind,
        name,
        description: node.description().map(str::to_owned),
        bounds,
        disabled: node.is_disabled(),
    })
}

/// Removes the number box egui draws after a slider to show and type its
/// value: it has no name of its own, and the slider already says the value.
fn drop_slider_value_boxes(items: &mut Vec<Item>) {
    let mut keep = vec![true; items.len()];
    for i in 1..items.len() {
        if let (
            Kind::Slider { min, max, .. },
            Kind::Number {
                min: lo, max: hi, ..
            },
        ) = (&items[i - 1].kind, &items[i].kind)
        {
            let same_range = *lo == Some(*min) && *hi == Some(*max);
            if same_range && items[i].name.is_empty() && items[i].parent == items[i - 1].parent {
                keep[i] = false;
            }
        }
    }
    let mut flags = keep.into_iter();
    items.retain(|_| flags.next().unwrap_or(true));
}

/// Removes a label that the control right after it is named by (a settings
/// row's label and its slider): the control says it, once.
fn drop_repeated_labels(items: &mut Vec<Item>) {
    let mut keep = vec![true; items.len()];
    for i in 0..items.len().saturating_sub(1) {
        let (label, control) = (&items[i], &items[i + 1]);
        if label.kind == Kind::Text
            && control.kind.is_control()
            && control.parent == label.parent
            && control.name == label.name
        {
            keep[i] = false;
        }
    }
    let mut flags = keep.into_iter();
    items.retain(|_| flags.next().unwrap_or(true));
}

/// Removes groups with nothing inside them (a panel egui laid out but left
/// empty this frame), innermost first.
fn drop_empty_groups(items: &mut Vec<Item>) {
    loop {
        let parents: std::collections::HashSet<u64> =
            items.iter().filter_map(|i| i.parent).collect();
        let before = items.len();
        items.retain(|i| !i.kind.is_group() || parents.contains(&i.id));
        if items.len() == before {
            return;
        }
    }
}
