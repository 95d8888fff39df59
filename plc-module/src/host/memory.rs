//! A loaded module's variables for the runtime: the program's image itself, read and written
//! value by value through its descriptor (as tools do), with the bit mapping kept as the
//! derive keeps it (a bit-mapped bool and its source word change together), and the module's
//! own code for unpacking and packing bits.

use super::schema::schema_of;
use crate::Module;
use plc_core::memory::{Memory, Schema};
use plc_core::{SetError, Value, VarInfo};
use plc_rules::path::leaf;
use plc_shm::codec::{decode, encode};
use std::sync::Arc;

/// The variables of a program run from a module: its image and what describes it. Cloning
/// copies the image, not the module.
///
/// ```no_run
/// use plc_module::{Module, ModuleMemory, trial::Trial};
/// use plc_core::memory::Memory;
///
/// let module = Module::load("target/release/libconveyor.so", &Trial::this_program()?)?;
/// let gm = ModuleMemory::initial(std::sync::Arc::new(module))?;
/// println!("{} variables", gm.schema().variables.len());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Clone, Debug)]
pub struct ModuleMemory {
    image: Vec<u8>,
    schema: Schema,
    module: Arc<Module>,
    /// A panic in the module's bit packing, for the next tick to report (the runtime calls
    /// those outside the tick's protection).
    fault: Option<String>,
}

impl ModuleMemory {
    /// The module's variables at their initial values.
    pub fn initial(module: Arc<Module>) -> Result<ModuleMemory, crate::ModuleFault> {
        let image = module.initial_image()?;
        let schema = schema_of(module.descriptor(), module.info().bus.as_ref());
        Ok(ModuleMemory {
            image,
            schema,
            module,
            fault: None,
        })
    }

    /// The module that runs over these variables.
    pub fn module(&self) -> &Arc<Module> {
        &self.module
    }

    /// The image.
    pub fn image(&self) -> &[u8] {
        &self.image
    }

    /// The image, for the module's tick.
    pub fn image_mut(&mut self) -> &mut [u8] {
        &mut self.image
    }

    /// A panic of the module's bit packing since the last call, if any.
    pub fn take_fault(&mut self) -> Option<String> {
        self.fault.take()
    }

    fn var(&self, index: usize) -> Option<&'static VarInfo> {
        self.schema.variables.get(index)
    }

    /// Writes `value` (fitted) at leaf `element` of variable `index`.
    fn store(&mut self, index: usize, element: usize, value: Value) -> Result<(), SetError> {
        let vars = self.schema.variables;
        let top = self.var(index).ok_or(SetError::UnknownIndex { index })?;
        let found = leaf(vars, index, element).ok_or(SetError::ElementOutOfRange {
            name: top.name,
            element,
            len: top.leaves(),
        })?;
        let node = found.node;
        let fitted = value
            .fit(node.iec_type, node.string_capacity())
            .map_err(|error| SetError::Value {
                name: node.name,
                error,
            })?;
        let size = node.element_size();
        let bytes = self
            .image
            .get_mut(found.offset..found.offset + size)
            .ok_or(SetError::UnknownIndex { index })?;
        if !encode(node.iec_type, &fitted, bytes) {
            return Err(SetError::Value {
                name: node.name,
                error: plc_core::ValueError::WrongKind {
                    expected: node.iec_type,
                    found: fitted.kind(),
                },
            });
        }
        Ok(())
    }

    /// The bit `bit` of top-level variable `source`'s first element.
    fn word_bit(&self, source: usize, bit: u8) -> Option<bool> {
        let raw = self
            .try_get(source, 0)?
            .to_raw_bits(self.var(source)?.iec_type);
        Some(raw >> bit & 1 == 1)
    }

    fn set_word_bit(&mut self, source: usize, bit: u8, on: bool) {
        let Some(var) = self.var(source) else { return };
        let Some(word) = self.try_get(source, 0) else {
            return;
        };
        let raw = word.to_raw_bits(var.iec_type);
        let raw = if on {
            raw | 1 << bit
        } else {
            raw & !(1 << bit)
        };
        let bits = var.iec_type.image_size() as u32 * 8;
        let _ = self.store(source, 0, Value::from_raw_bits(raw, var.iec_type, bits));
    }

    /// Each bool mapped onto a bit of some word: its index, source and bit.
    fn mapped(&self) -> impl Iterator<Item = (usize, usize, u8)> + 'static {
        self.schema
            .variables
            .iter()
            .enumerate()
            .filter_map(|(i, v)| v.bit.map(|b| (i, b.source, b.bit)))
    }

    fn call(&mut self, pack: bool) {
        let module = self.module.clone();
        let done = if pack {
            module.pack_bits(&mut self.image)
        } else {
            module.unpack_bits(&mut self.image)
        };
        if let Err(fault) = done {
            self.fault.get_or_insert(fault.to_string());
        }
    }
}

impl Memory for ModuleMemory {
    type Image = Vec<u8>;

    fn schema(&self) -> Schema {
        self.schema
    }

    fn new_image(&self) -> Vec<u8> {
        vec![0; self.image.len()]
    }

    fn image_bytes(image: &Vec<u8>) -> &[u8] {
        image
    }

    fn store_image(&self, image: &mut Vec<u8>) {
        image.clear();
        image.extend_from_slice(&self.image);
    }

    fn load_image(&mut self, image: &Vec<u8>) {
        if image.len() == self.image.len() {
            self.image.copy_from_slice(image);
        }
    }

    fn unpack_bits(&mut self) {
        self.call(false);
    }

    fn pack_bits(&mut self) {
        self.call(true);
    }

    fn try_get(&self, index: usize, element: usize) -> Option<Value> {
        let found = leaf(self.schema.variables, index, element)?;
        let size = found.node.element_size();
        let bytes = self.image.get(found.offset..found.offset + size)?;
        Some(decode(found.node.iec_type, bytes))
    }

    fn set(&mut self, index: usize, element: usize, value: Value) -> Result<(), SetError> {
        self.store(index, element, value)?;
        let var = self.var(index).ok_or(SetError::UnknownIndex { index })?;
        // The derive's rule: a bit-mapped bool sets its bit of the source word, and a source
        // word sets the bools mapped onto it.
        if let Some(b) = var.bit {
            let on = self.try_get(index, 0) == Some(Value::Bool(true));
            self.set_word_bit(b.source, b.bit, on);
        }
        let bools: Vec<(usize, u8)> = self
            .mapped()
            .filter(|&(_, source, _)| source == index)
            .map(|(i, _, bit)| (i, bit))
            .collect();
        for (i, bit) in bools {
            if let Some(on) = self.word_bit(index, bit) {
                let _ = self.store(i, 0, Value::Bool(on));
            }
        }
        Ok(())
    }
}
