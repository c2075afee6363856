//! Styles of the TUI. With `NO_COLOR` set every colour is dropped and only
//! bold / dim / reversed / underline mark things.

use ratatui::style::{Color, Modifier, Style};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Theme {
    pub color: bool,
}

/// What a colour in the picture stands for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ink {
    Body,
    BodyAfter,
    Ground,
    Normal,
    Arm,
    VelocityBefore,
    VelocityAfter,
    Impulse,
    Point,
}

impl Theme {
    /// Colour unless `NO_COLOR` is set to anything (https://no-color.org).
    pub fn from_env() -> Self {
        Theme {
            color: std::env::var_os("NO_COLOR").is_none(),
        }
    }

    fn fg(&self, c: Color) -> Style {
        if self.color {
            Style::new().fg(c)
        } else {
            Style::new()
        }
    }

    pub fn ink(&self, ink: Ink) -> Color {
        if !self.color {
            return Color::Reset;
        }
        match ink {
            Ink::Body => Color::White,
            Ink::BodyAfter => Color::DarkGray,
            Ink::Ground => Color::Gray,
            Ink::Normal => Color::Yellow,
            Ink::Arm => Color::Cyan,
            Ink::VelocityBefore => Color::Blue,
            Ink::VelocityAfter => Color::Green,
            Ink::Impulse => Color::Red,
            Ink::Point => Color::Magenta,
        }
    }

    pub fn ink_style(&self, ink: Ink) -> Style {
        self.fg(self.ink(ink)).add_modifier(Modifier::BOLD)
    }

    pub fn title(&self) -> Style {
        self.fg(Color::Cyan).add_modifier(Modifier::BOLD)
    }
    pub fn border(&self) -> Style {
        self.fg(Color::DarkGray)
    }
    pub fn border_focus(&self) -> Style {
        self.fg(Color::Cyan)
    }
    /// The current item of a list.
    pub fn selected(&self) -> Style {
        Style::new().add_modifier(Modifier::REVERSED | Modifier::BOLD)
    }
    /// Skipped stages, notes, hints.
    pub fn dim(&self) -> Style {
        if self.color {
            Style::new().fg(Color::DarkGray)
        } else {
            Style::new().add_modifier(Modifier::DIM)
        }
    }
    pub fn note(&self) -> Style {
        self.fg(Color::Gray).add_modifier(Modifier::ITALIC)
    }
    /// A formula's symbolic line.
    pub fn formula(&self) -> Style {
        self.fg(Color::White)
    }
    /// The numbers put into a formula.
    pub fn substituted(&self) -> Style {
        self.fg(Color::Gray)
    }
    /// A stage's result.
    pub fn result(&self) -> Style {
        self.fg(Color::Green).add_modifier(Modifier::BOLD)
    }
    /// A value that changed with the last edit.
    pub fn changed(&self) -> Style {
        self.fg(Color::Yellow)
            .add_modifier(Modifier::BOLD | Modifier::UNDERLINED)
    }
    /// A result hidden in predict mode.
    pub fn hidden(&self) -> Style {
        self.fg(Color::Magenta).add_modifier(Modifier::BOLD)
    }
    pub fn pass(&self) -> Style {
        self.fg(Color::Green).add_modifier(Modifier::BOLD)
    }
    pub fn fail(&self) -> Style {
        self.fg(Color::Red)
            .add_modifier(Modifier::BOLD | Modifier::REVERSED)
    }
    pub fn error(&self) -> Style {
        self.fg(Color::Red).add_modifier(Modifier::BOLD)
    }
    pub fn info(&self) -> Style {
        self.fg(Color::Green)
    }
    pub fn key(&self) -> Style {
        self.fg(Color::Cyan).add_modifier(Modifier::BOLD)
    }
    pub fn warning(&self) -> Style {
        self.fg(Color::Yellow)
    }
}
