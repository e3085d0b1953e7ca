package org.habla.draw;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Locale;

/**
 * HABLA's one SVG writer: the graph drawing ({@link SvgWriter}) and the simulator's scenario plots both write
 * with it. Elements come out in the order written, their attributes in the order given, one element a line,
 * indented two spaces a level; every attribute value and text is escaped, every number has at most one decimal
 * and is the same on every machine. Not a general SVG library: no DOM, no styles beyond attributes.
 *
 * <pre>
 *   SvgDocument svg = new SvgDocument(200, 100);
 *   svg.element("rect").attr("width", 200).attr("height", 100).attr("fill", "white").end();
 *   svg.element("path").attr("d", "M0,0 L10,10").attr("stroke", "black").title("a → b");
 *   svg.element("g").attr("class", "legend").open();
 *   svg.element("text").attr("x", 5.25).attr("y", 20).text("a < b");
 *   svg.close();
 *   String xml = svg.render();
 * </pre>
 *
 * <p>Not thread-safe: one document is written by one thread.
 */
public final class SvgDocument {

    private static final String NAMESPACE = "http://www.w3.org/2000/svg";

    private final StringBuilder root = new StringBuilder();
    private final StringBuilder body = new StringBuilder();
    private final Deque<String> open = new ArrayDeque<>();

    /** A document {@code width} × {@code height} user units (pixels), its view box the same. */
    public SvgDocument(double width, double height) {
        root.append("<svg xmlns=\"").append(NAMESPACE).append("\" width=\"").append(number(width))
                .append("\" height=\"").append(number(height)).append("\" viewBox=\"0 0 ").append(number(width))
                .append(' ').append(number(height)).append('"');
    }

    /** Adds an attribute to the {@code <svg>} element itself (a default font, say). */
    public SvgDocument rootAttribute(String name, String value) {
        root.append(' ').append(name).append("=\"").append(escape(value)).append('"');
        return this;
    }

    /** Starts an element; nothing is written until it is finished by {@link Element#end}, {@code title}, … */
    public Element element(String name) {
        return new Element(name);
    }

    /** Closes the element last {@linkplain Element#open() opened}. */
    public SvgDocument close() {
        if (open.isEmpty()) {
            throw new IllegalStateException("no element is open");
        }
        String name = open.pop();
        line("</" + name + ">");
        return this;
    }

    /** The whole document, every opened element closed. */
    public String render() {
        if (!open.isEmpty()) {
            throw new IllegalStateException("elements still open: " + open);
        }
        return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + root + ">\n" + body + "</svg>\n";
    }

    /** A number with at most one decimal, without a trailing {@code .0}: the same text on every machine. */
    public static String number(double v) {
        double r = Math.round(v * 10) / 10.0;
        return r == Math.rint(r) ? Long.toString((long) r) : String.format(Locale.ROOT, "%.1f", r);
    }

    /**
     * {@code text} safe inside an attribute value or an element: the five XML specials as entities, and control
     * characters, which XML 1.0 cannot carry, as spaces.
     */
    public static String escape(String text) {
        StringBuilder out = new StringBuilder(text.length());
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            switch (c) {
                case '&' -> out.append("&amp;");
                case '<' -> out.append("&lt;");
                case '>' -> out.append("&gt;");
                case '"' -> out.append("&quot;");
                case '\'' -> out.append("&apos;");
                default -> out.append(c < 0x20 && c != '\t' && c != '\n' ? ' ' : c);
            }
        }
        return out.toString();
    }

    private void line(String markup) {
        body.append("  ".repeat(open.size() + 1)).append(markup).append('\n');
    }

    /** An element being written: its attributes, then one way of finishing it. */
    public final class Element {

        private final String name;
        private final StringBuilder tag = new StringBuilder();

        private Element(String name) {
            this.name = name;
            tag.append('<').append(name);
        }

        public Element attr(String attribute, String value) {
            tag.append(' ').append(attribute).append("=\"").append(escape(value)).append('"');
            return this;
        }

        /** A numeric attribute, written by {@link #number}. */
        public Element attr(String attribute, double value) {
            return attr(attribute, number(value));
        }

        /** Writes the element empty: {@code <name …/>}. */
        public SvgDocument end() {
            line(tag + "/>");
            return SvgDocument.this;
        }

        /** Writes the element with a {@code <title>} that viewers show on hover; empty if {@code title} is null. */
        public SvgDocument title(String title) {
            if (title == null) {
                return end();
            }
            line(tag + "><title>" + escape(title) + "</title></" + name + ">");
            return SvgDocument.this;
        }

        /** Writes the element holding {@code text}. */
        public SvgDocument text(String text) {
            line(tag + ">" + escape(text) + "</" + name + ">");
            return SvgDocument.this;
        }

        /** Writes the element holding one empty element on the same line (a marker's shape). */
        public SvgDocument around(Element child) {
            line(tag + ">" + child.tag + "/></" + name + ">");
            return SvgDocument.this;
        }

        /** Writes the start tag: what is written next goes inside, until {@link SvgDocument#close()}. */
        public SvgDocument open() {
            line(tag + ">");
            open.push(name);
            return SvgDocument.this;
        }
    }
}
