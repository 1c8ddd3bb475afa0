//! A command key that takes `false` (or `null`) to switch something off, or
//! an object to switch it on or change it: `compare`, `lesson`.

use serde::Deserialize;
use serde::de::{Deserializer, MapAccess, Visitor};

/// `false` / `null`, or an object `T`.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "schema", schemars(untagged))]
pub enum OffOr<T> {
    /// `false` or `null`: switch it off.
    #[cfg_attr(feature = "schema", schemars(with = "Option<False>"))]
    Off,
    /// Switch it on or change it.
    On(T),
}

/// The JSON value `false`, for the schema.
#[cfg(feature = "schema")]
struct False;

#[cfg(feature = "schema")]
impl schemars::JsonSchema for False {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "False".into()
    }
    fn json_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
        schemars::json_schema!({ "const": false })
    }
}

impl<'de, T: Deserialize<'de>> Deserialize<'de> for OffOr<T> {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Value<T>(std::marker::PhantomData<T>);
        impl<'de, T: Deserialize<'de>> Visitor<'de> for Value<T> {
            type Value = OffOr<T>;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("an object or false")
            }
            fn visit_bool<E: serde::de::Error>(self, on: bool) -> Result<OffOr<T>, E> {
                if on {
                    Err(E::invalid_type(serde::de::Unexpected::Bool(true), &self))
                } else {
                    Ok(OffOr::Off)
                }
            }
            fn visit_unit<E: serde::de::Error>(self) -> Result<OffOr<T>, E> {
                Ok(OffOr::Off)
            }
            fn visit_none<E: serde::de::Error>(self) -> Result<OffOr<T>, E> {
                Ok(OffOr::Off)
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<OffOr<T>, A::Error> {
                T::deserialize(serde::de::value::MapAccessDeserializer::new(map)).map(OffOr::On)
            }
        }
        deserializer.deserialize_any(Value(std::marker::PhantomData))
    }
}
