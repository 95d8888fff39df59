//! The Sparkplug B topic namespace: `spBv1.0/GROUP/TYPE/NODE[/DEVICE]` and
//! `spBv1.0/STATE/HOST`.

use std::fmt;

/// The namespace's first level.
pub const NAMESPACE: &str = "spBv1.0";

/// The message types of an edge node's topics.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MessageType {
    /// The node's birth.
    NBirth,
    /// The node's death (also its MQTT Will).
    NDeath,
    /// The node's data.
    NData,
    /// A command to the node.
    NCmd,
    /// A device's birth.
    DBirth,
    /// A device's death.
    DDeath,
    /// A device's data.
    DData,
    /// A command to a device.
    DCmd,
}

impl MessageType {
    /// The topic level, e.g. `NBIRTH`.
    pub fn name(self) -> &'static str {
        match self {
            MessageType::NBirth => "NBIRTH",
            MessageType::NDeath => "NDEATH",
            MessageType::NData => "NDATA",
            MessageType::NCmd => "NCMD",
            MessageType::DBirth => "DBIRTH",
            MessageType::DDeath => "DDEATH",
            MessageType::DData => "DDATA",
            MessageType::DCmd => "DCMD",
        }
    }

    fn parse(s: &str) -> Option<MessageType> {
        Some(match s {
            "NBIRTH" => MessageType::NBirth,
            "NDEATH" => MessageType::NDeath,
            "NDATA" => MessageType::NData,
            "NCMD" => MessageType::NCmd,
            "DBIRTH" => MessageType::DBirth,
            "DDEATH" => MessageType::DDeath,
            "DDATA" => MessageType::DData,
            "DCMD" => MessageType::DCmd,
            _ => return None,
        })
    }

    /// Whether its topic names a device.
    pub fn is_device(self) -> bool {
        matches!(
            self,
            MessageType::DBirth | MessageType::DDeath | MessageType::DData | MessageType::DCmd
        )
    }
}

/// A parsed topic.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Topic {
    /// An edge node's or device's message.
    Node {
        /// The group id.
        group: String,
        /// The message type.
        kind: MessageType,
        /// The edge node id.
        node: String,
        /// The device id (device messages only).
        device: Option<String>,
    },
    /// A host application's STATE.
    State {
        /// The host id.
        host: String,
    },
}

impl Topic {
    /// An edge node's topic (`device` none) or a device's.
    pub fn node(group: &str, kind: MessageType, node: &str, device: Option<&str>) -> Topic {
        Topic::Node {
            group: group.to_string(),
            kind,
            node: node.to_string(),
            device: device.map(str::to_string),
        }
    }

    /// Parses a topic; `None` for one outside the namespace or of the wrong shape.
    ///
    /// ```
    /// use plc_sparkplug::topic::{MessageType, Topic};
    /// let t = Topic::parse("spBv1.0/plant/DCMD/line1/press").unwrap();
    /// assert_eq!(t, Topic::node("plant", MessageType::DCmd, "line1", Some("press")));
    /// assert_eq!(t.to_string(), "spBv1.0/plant/DCMD/line1/press");
    /// ```
    pub fn parse(topic: &str) -> Option<Topic> {
        let mut levels = topic.split('/');
        if levels.next()? != NAMESPACE {
            return None;
        }
        let parts: Vec<&str> = levels.collect();
        if parts.iter().any(|p| p.is_empty()) {
            return None;
        }
        match parts.as_slice() {
            ["STATE", host] => Some(Topic::State {
                host: host.to_string(),
            }),
            [group, kind, node] => {
                let kind = MessageType::parse(kind).filter(|k| !k.is_device())?;
                Some(Topic::node(group, kind, node, None))
            }
            [group, kind, node, device] => {
                let kind = MessageType::parse(kind).filter(|k| k.is_device())?;
                Some(Topic::node(group, kind, node, Some(device)))
            }
            _ => None,
        }
    }
}

impl fmt::Display for Topic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Topic::State { host } => write!(f, "{NAMESPACE}/STATE/{host}"),
            Topic::Node {
                group,
                kind,
                node,
                device,
            } => {
                write!(f, "{NAMESPACE}/{group}/{}/{node}", kind.name())?;
                match device {
                    Some(d) => write!(f, "/{d}"),
                    None => Ok(()),
                }
            }
        }
    }
}

/// Checks a group, node or device id or a host id: the specification allows any UTF-8 but the
/// MQTT separators and wildcards (`/`, `+`, `#`), and none may be empty.
pub fn check_id(what: &str, id: &str) -> Result<(), String> {
    if id.is_empty() || id.contains(['/', '+', '#']) {
        return Err(format!(
            "the {what} `{id}` cannot be a Sparkplug id: give a non-empty name without `/`, `+` \
             or `#`"
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_node_and_device_topic_reads_back_as_written() {
        for kind in [
            MessageType::NBirth,
            MessageType::NDeath,
            MessageType::NData,
            MessageType::NCmd,
        ] {
            let t = Topic::node("g", kind, "n", None);
            assert_eq!(Topic::parse(&t.to_string()), Some(t));
        }
        for kind in [
            MessageType::DBirth,
            MessageType::DDeath,
            MessageType::DData,
            MessageType::DCmd,
        ] {
            let t = Topic::node("g", kind, "n", Some("d"));
            assert_eq!(Topic::parse(&t.to_string()), Some(t));
        }
        let state = Topic::State {
            host: "scada".into(),
        };
        assert_eq!(state.to_string(), "spBv1.0/STATE/scada");
        assert_eq!(Topic::parse("spBv1.0/STATE/scada"), Some(state));
    }

    #[test]
    fn topics_of_the_wrong_shape_are_not_parsed() {
        for bad in [
            "",
            "spBv1.0",
            "spAv1.0/g/NCMD/n",
            "spBv1.0/g/NCMD/n/d",
            "spBv1.0/g/DCMD/n",
            "spBv1.0/g/XCMD/n",
            "spBv1.0/g//n",
            "spBv1.0/g/DCMD/n/d/extra",
            "spBv1.0/STATE/",
        ] {
            assert_eq!(Topic::parse(bad), None, "{bad}");
        }
    }

    #[test]
    fn ids_with_mqtt_separators_or_wildcards_are_refused() {
        assert!(check_id("group", "plant-1").is_ok());
        for bad in ["", "a/b", "a+", "#"] {
            let e = check_id("group", bad).unwrap_err();
            assert!(e.contains("give a non-empty name"), "{e}");
        }
    }
}
