use super::{cells, convert};

#[test]
fn letters_numbers_and_operators() {
    assert_eq!(
        convert("\\Delta v = -(1 + c)\\cdot v_s"),
        "<mi mathvariant=\"normal\">Δ</mi><mi>v</mi><mo>=</mo><mo>−</mo><mo>(</mo><mn>1</mn>\
         <mo>+</mo><mi>c</mi><mo>)</mo><mo>·</mo><msub><mi>v</mi><mi>s</mi></msub>"
    );
    assert_eq!(convert("0.71513"), "<mn>0.71513</mn>");
    assert_eq!(
        convert("-2.69956 \\times 10^{-5}"),
        "<mo>−</mo><mn>2.69956</mn><mo>×</mo><msup><mn>10</mn><mrow><mo>−</mo><mn>5</mn></mrow></msup>"
    );
}

#[test]
fn accents_scripts_and_upright_names() {
    assert_eq!(
        convert("\\Delta \\dot{\\theta}_{d,1}"),
        "<mi mathvariant=\"normal\">Δ</mi><msub><mover accent=\"true\"><mrow><mi>θ</mi></mrow>\
         <mo>˙</mo></mover><mrow><mi>d</mi><mo>,</mo><mn>1</mn></mrow></msub>"
    );
    assert_eq!(
        convert("\\hat{d}"),
        "<mover accent=\"true\"><mrow><mi>d</mi></mrow><mo>^</mo></mover>"
    );
    assert_eq!(
        convert("I_1^{-1}"),
        "<msubsup><mi>I</mi><mn>1</mn><mrow><mo>−</mo><mn>1</mn></mrow></msubsup>"
    );
    assert_eq!(
        convert("g_{\\mathrm{contact}}"),
        "<msub><mi>g</mi><mrow><mrow><mi>contact</mi></mrow></mrow></msub>"
    );
    assert_eq!(
        convert("\\mathrm{angular\\_limit}"),
        "<mrow><mi>angular_limit</mi></mrow>"
    );
    assert_eq!(convert("\\mathrm{atan2}"), "<mrow><mi>atan2</mi></mrow>");
    assert_eq!(
        convert("\\,\\mathrm{(m/s)/(N\\cdot s)}"),
        "<mspace width=\"0.1667em\"></mspace><mrow><mo>(</mo><mi mathvariant=\"normal\">m</mi><mo>/</mo>\
         <mi mathvariant=\"normal\">s</mi><mo>)</mo><mo>/</mo><mo>(</mo><mi mathvariant=\"normal\">N</mi>\
         <mo>·</mo><mi mathvariant=\"normal\">s</mi><mo>)</mo></mrow>"
    );
    assert_eq!(
        convert("C^{\\mathsf{T}}"),
        "<msup><mi>C</mi><mrow><mrow><mi mathvariant=\"normal\">T</mi></mrow></mrow></msup>"
    );
}

#[test]
fn roots_fractions_degrees_and_matrices() {
    assert_eq!(
        convert("\\sqrt{g_y^2}"),
        "<msqrt><mrow><msubsup><mi>g</mi><mi>y</mi><mn>2</mn></msubsup></mrow></msqrt>"
    );
    assert_eq!(
        convert("\\tfrac{1}{2}"),
        "<mfrac displaystyle=\"false\"><mrow><mn>1</mn></mrow><mrow><mn>2</mn></mrow></mfrac>"
    );
    assert_eq!(convert("0.2{}^{\\circ}"), "<mn>0.2</mn><mo>°</mo>");
    assert_eq!(
        convert("(5.9 \\times 10^{-5}){}^{\\circ}"),
        "<mo>(</mo><mn>5.9</mn><mo>×</mo><msup><mn>10</mn><mrow><mo>−</mo><mn>5</mn></mrow></msup>\
         <mo>)</mo><mo>°</mo>"
    );
    assert_eq!(
        convert("\\begin{pmatrix} 0 & 1 \\\\ -1 & 0 \\end{pmatrix}"),
        "<mrow><mo>(</mo><mtable><mtr><mtd><mn>0</mn></mtd><mtd><mn>1</mn></mtd></mtr>\
         <mtr><mtd><mo>−</mo><mn>1</mn></mtd><mtd><mn>0</mn></mtd></mtr></mtable><mo>)</mo></mrow>"
    );
}

#[test]
fn an_aligned_row_splits_at_the_ampersand_outside_matrices() {
    let row = cells("C &= \\begin{pmatrix} 0 & 1 \\\\ 1 & 0 \\end{pmatrix}");
    assert_eq!(row.len(), 2, "{row:?}");
    assert_eq!(row[0], "<mi>C</mi>");
    assert!(row[1].starts_with("<mo>=</mo><mrow><mo>(</mo><mtable>"));
    assert_eq!(cells("&= 1").len(), 2);
}

#[test]
fn what_it_does_not_know_is_an_error_not_a_silence_and_html_is_escaped() {
    assert_eq!(
        convert("\\frobnicate"),
        "<merror><mtext>\\frobnicate</mtext></merror>"
    );
    assert_eq!(convert("a < b"), "<mi>a</mi><mo>&lt;</mo><mi>b</mi>");
    // Unbalanced input ends; it does not loop.
    assert!(!convert("}{x").is_empty());
    assert!(!convert("x^").is_empty());
}
