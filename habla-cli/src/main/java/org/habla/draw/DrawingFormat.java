package org.habla.draw;

import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;

/** The formats {@code habla graph} writes. */
public enum DrawingFormat {
    DOT,
    MERMAID,
    SVG;

    /** The picture in this format. */
    public String write(GraphPicture picture) {
        return switch (this) {
            case DOT -> DotWriter.write(picture);
            case MERMAID -> MermaidWriter.write(picture);
            case SVG -> SvgWriter.write(picture);
        };
    }

    /** The format a file name asks for: {@code .dot}/{@code .gv}, {@code .mmd}/{@code .mermaid}, {@code .svg}. */
    public static Optional<DrawingFormat> ofFileName(Path file) {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (name.endsWith(".dot") || name.endsWith(".gv")) {
            return Optional.of(DOT);
        }
        if (name.endsWith(".mmd") || name.endsWith(".mermaid")) {
            return Optional.of(MERMAID);
        }
        if (name.endsWith(".svg")) {
            return Optional.of(SVG);
        }
        return Optional.empty();
    }
}
