package io.github.jdem846.cli;

import io.github.jdem846.overlay.Overlay;
import io.github.jdem846.overlay.OverlayFiles;
import io.github.jdem846.overlay.OverlayStyle;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;

/**
 * {@code --overlay FILE[:STYLE]}, repeatable: GeoJSON or shapefile features drawn onto the picture
 * ({@link io.github.jdem846.overlay.OverlayPainter}). The style after the last colon is only taken as a style when
 * it holds {@code key=value} pairs, so a path with a colon in it is not cut.
 */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
final class OverlayOptions {

    @Option(names = "--overlay", paramLabel = "FILE[:STYLE]",
            description = "Draw the lines, polygons and points of a GeoJSON (.geojson, .json; lon/lat WGS 84) or "
                    + "shapefile (.shp, CRS from its .prj) onto the picture; repeatable, drawn in order. STYLE: "
                    + "comma-separated color=#RRGGBB[AA]|name, width=PX, fill=#RRGGBBAA|none, radius=PX "
                    + "(default color=#b2182b,width=1.5,fill=none,radius=3).")
    List<String> overlays = new ArrayList<>();

    /** @return true when at least one overlay was given */
    boolean given() {
        return !overlays.isEmpty();
    }

    /** Checks each style while parsing is still the user's to fix: a bad one is a usage error (exit 2). */
    void requireValidStyles(CommandSpec spec) {
        for (String arg : overlays) {
            Usage.check(spec, "--overlay", () -> split(arg));
        }
    }

    /**
     * Reads the overlay files.
     *
     * @return the overlays, in the order given
     * @throws IOException when a file is missing or not readable as GeoJSON or a shapefile (one line naming it)
     */
    List<Overlay> read() throws IOException {
        List<Overlay> out = new ArrayList<>();
        for (String arg : overlays) {
            Spec s = split(arg);
            out.add(OverlayFiles.read(s.file(), s.style()));
        }
        return out;
    }

    private record Spec(Path file, OverlayStyle style) {
    }

    private static Spec split(String arg) {
        int colon = arg.lastIndexOf(':');
        if (colon > 0 && arg.indexOf('=', colon) > colon) {
            return new Spec(Path.of(arg.substring(0, colon)), OverlayStyle.parse(arg.substring(colon + 1)));
        }
        return new Spec(Path.of(arg), OverlayStyle.DEFAULT);
    }
}
