//! Reading fuzz input: a byte cursor that yields zeros once the input is
//! used up, so every byte string decodes to some case (short inputs are
//! small cases, which keeps the corpus small).

pub struct Bytes<'a> {
    data: &'a [u8],
}

impl<'a> Bytes<'a> {
    pub fn new(data: &'a [u8]) -> Self {
        Self { data }
    }

    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }

    pub fn u8(&mut self) -> u8 {
        match self.data.split_first() {
            Some((&b, rest)) => {
                self.data = rest;
                b
            }
            None => 0,
        }
    }

    pub fn i8(&mut self) -> i8 {
        self.u8() as i8
    }

    pub fn i16(&mut self) -> i16 {
        i16::from_le_bytes([self.u8(), self.u8()])
    }

    pub fn i32(&mut self) -> i32 {
        i32::from_le_bytes([self.u8(), self.u8(), self.u8(), self.u8()])
    }

    pub fn u32(&mut self) -> u32 {
        self.i32() as u32
    }
}
