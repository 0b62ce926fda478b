//! A grayscale image as `f32` intensities (0–255), decoded from JPEG/PNG bytes, with the few
//! operations the detector needs: Gaussian smoothing, bilinear sampling and central gradients.
//!
//! Pixel `(x, y)` is the centre of column `x`, row `y` (ARCHITECTURE.md's image space: origin at the
//! top-left pixel's centre), the convention OpenCV's corner positions use.

use crate::error::{CalibrationError, Result};

/// A grayscale image, row-major.
#[derive(Debug, Clone, PartialEq)]
pub struct GrayImage {
    width: usize,
    height: usize,
    data: Vec<f32>,
}

impl GrayImage {
    /// An image from row-major intensities; `None` when the buffer does not match the size.
    pub fn from_vec(width: usize, height: usize, data: Vec<f32>) -> Option<Self> {
        (width > 0 && height > 0 && data.len() == width * height).then_some(Self {
            width,
            height,
            data,
        })
    }

    /// Decodes JPEG or PNG bytes (colour is converted to luma). `name` labels errors.
    pub fn decode(bytes: &[u8], name: &str) -> Result<Self> {
        let img = image::load_from_memory(bytes).map_err(|e| CalibrationError::Decode {
            name: name.to_owned(),
            message: e.to_string(),
        })?;
        let luma = img.to_luma8();
        let (w, h) = luma.dimensions();
        let data = luma.into_raw().into_iter().map(f32::from).collect();
        Self::from_vec(w as usize, h as usize, data).ok_or_else(|| CalibrationError::Decode {
            name: name.to_owned(),
            message: format!("empty image ({w}x{h})"),
        })
    }

    /// Width in pixels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// `(width, height)` as `u32`, the camera model's image size.
    pub fn size_px(&self) -> (u32, u32) {
        (self.width as u32, self.height as u32)
    }

    /// Intensity at an integer pixel, clamped to the border.
    #[inline]
    pub fn at(&self, x: isize, y: isize) -> f32 {
        let xc = x.clamp(0, self.width as isize - 1) as usize;
        let yc = y.clamp(0, self.height as isize - 1) as usize;
        self.data[yc * self.width + xc]
    }

    /// Bilinear intensity at a sub-pixel position (clamped to the border).
    #[inline]
    pub fn sample(&self, x: f64, y: f64) -> f64 {
        let x0 = x.floor();
        let y0 = y.floor();
        let (fx, fy) = (x - x0, y - y0);
        let (xi, yi) = (x0 as isize, y0 as isize);
        let a = f64::from(self.at(xi, yi));
        let b = f64::from(self.at(xi + 1, yi));
        let c = f64::from(self.at(xi, yi + 1));
        let d = f64::from(self.at(xi + 1, yi + 1));
        (a * (1.0 - fx) + b * fx) * (1.0 - fy) + (c * (1.0 - fx) + d * fx) * fy
    }

    /// A separable Gaussian blur with standard deviation `sigma_px` (kernel radius 3σ, border
    /// pixels repeated).
    #[must_use]
    pub fn gaussian_blur(&self, sigma_px: f64) -> Self {
        if sigma_px <= 0.0 {
            return self.clone();
        }
        let radius = (3.0 * sigma_px).ceil() as usize;
        let kernel: Vec<f32> = (0..=2 * radius)
            .map(|i| {
                let d = i as f64 - radius as f64;
                (-(d * d) / (2.0 * sigma_px * sigma_px)).exp() as f32
            })
            .collect();
        let norm: f32 = kernel.iter().sum();
        let kernel: Vec<f32> = kernel.iter().map(|k| k / norm).collect();
        let (w, h) = (self.width, self.height);
        // horizontal pass on a border-padded copy of each row
        let mut tmp = vec![0.0f32; w * h];
        let mut padded = vec![0.0f32; w + 2 * radius];
        for y in 0..h {
            let row = &self.data[y * w..(y + 1) * w];
            padded[radius..radius + w].copy_from_slice(row);
            padded[..radius].fill(row[0]);
            padded[radius + w..].fill(row[w - 1]);
            let out = &mut tmp[y * w..(y + 1) * w];
            for (x, o) in out.iter_mut().enumerate() {
                *o = kernel
                    .iter()
                    .zip(&padded[x..=x + 2 * radius])
                    .map(|(k, v)| k * v)
                    .sum();
            }
        }
        // vertical pass: whole rows at a time
        let mut out = vec![0.0f32; w * h];
        for y in 0..h {
            let dst = &mut out[y * w..(y + 1) * w];
            for (k, &kv) in kernel.iter().enumerate() {
                let sy = (y + k).saturating_sub(radius).min(h - 1);
                let src = &tmp[sy * w..(sy + 1) * w];
                for (d, s) in dst.iter_mut().zip(src) {
                    *d += kv * s;
                }
            }
        }
        Self {
            width: w,
            height: h,
            data: out,
        }
    }

    /// The intensities, row-major.
    pub fn data(&self) -> &[f32] {
        &self.data
    }

    /// Central-difference gradient `(∂I/∂x, ∂I/∂y)` at an integer pixel.
    #[inline]
    pub fn gradient(&self, x: isize, y: isize) -> (f64, f64) {
        (
            0.5 * f64::from(self.at(x + 1, y) - self.at(x - 1, y)),
            0.5 * f64::from(self.at(x, y + 1) - self.at(x, y - 1)),
        )
    }
}
