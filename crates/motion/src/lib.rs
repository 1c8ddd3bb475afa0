//! gaitlab-motion: kinematic drivers (She 2006 §5.2 target scripts).
