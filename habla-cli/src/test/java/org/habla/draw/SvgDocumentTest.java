package org.habla.draw;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import org.junit.jupiter.api.Test;

class SvgDocumentTest {

    @Test
    void elementsComeOutInOrderIndentedByNestingWithTheirAttributesInTheOrderGiven() {
        SvgDocument svg = new SvgDocument(200, 100.25).rootAttribute("font-size", "12");
        svg.element("g").attr("class", "legend").open();
        svg.element("rect").attr("x", 1.04).attr("width", 2.96).end();
        svg.element("path").attr("d", "M0,0").title("a → b");
        svg.close();
        svg.element("text").attr("y", -3.5).text("hi");

        assertThat(svg.render()).isEqualTo("""
                <?xml version="1.0" encoding="UTF-8"?>
                <svg xmlns="http://www.w3.org/2000/svg" width="200" height="100.3" viewBox="0 0 200 100.3" \
                font-size="12">
                  <g class="legend">
                    <rect x="1" width="3"/>
                    <path d="M0,0"><title>a → b</title></path>
                  </g>
                  <text y="-3.5">hi</text>
                </svg>
                """);
    }

    @Test
    void textAndAttributesAreEscapedAndControlCharactersBecomeSpaces() {
        SvgDocument svg = new SvgDocument(10, 10);
        svg.element("text").attr("id", "\"q\"").text("a<b & 'c'\u0007>");

        assertThat(svg.render()).contains("<text id=\"&quot;q&quot;\">a&lt;b &amp; &apos;c&apos; &gt;</text>");
        assertThat(DrawingTest.parse(svg.render()).getDocumentElement().getTagName()).isEqualTo("svg");
    }

    @Test
    void aMarkerHoldsItsShapeOnOneLineAndANullTitleLeavesTheElementEmpty() {
        SvgDocument svg = new SvgDocument(10, 10);
        svg.element("marker").attr("id", "m").around(svg.element("path").attr("fill", "red"));
        svg.element("circle").attr("r", 2).title(null);

        assertThat(svg.render()).contains("  <marker id=\"m\"><path fill=\"red\"/></marker>\n")
                .contains("  <circle r=\"2\"/>\n");
    }

    @Test
    void anElementLeftOpenOrClosedTwiceIsAnError() {
        SvgDocument svg = new SvgDocument(10, 10);
        svg.element("g").open();
        assertThatThrownBy(svg::render).hasMessageContaining("g");
        svg.close();
        assertThatThrownBy(svg::close).isInstanceOf(IllegalStateException.class);
    }
}
