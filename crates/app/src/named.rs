//! The command API's named values: a string in JSON, an enum once read, an
//! `enum` list in the schema. `named!` declares one
//! such newtype; an unknown name reads `unknown mode "fly" (walk, run, …)`.
//! A leaf module, so each feature declares its own names beside its command.

/// Declares a newtype over an enum that reads from a JSON string with
/// `$parse`, errs with the names in its list, and has that list as its
/// schema.
macro_rules! named {
    ($(#[$doc:meta])* $name:ident($inner:ty), $what:literal, $parse:expr, [$($v:literal),+ $(,)?]) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub struct $name(pub $inner);

        impl<'de> serde::Deserialize<'de> for $name {
            fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
                let text = <String as serde::Deserialize>::deserialize(deserializer)?;
                ($parse)(text.as_str()).map($name).ok_or_else(|| {
                    <D::Error as serde::de::Error>::custom(format!(
                        "unknown {} {text:?} ({})",
                        $what,
                        [$($v),+].join(", ")
                    ))
                })
            }
        }

        #[cfg(feature = "schema")]
        impl schemars::JsonSchema for $name {
            fn schema_name() -> std::borrow::Cow<'static, str> {
                stringify!($name).into()
            }
            fn json_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
                schemars::json_schema!({ "type": "string", "enum": [$($v),+] })
            }
        }
    };
}

pub(crate) use named;
