package io.github.jdem846.cli;

import io.github.jdem846.geo.LatLonBox;
import io.github.jdem846.projection.MapProjection;
import io.github.jdem846.projection.ProjectedRender;
import io.github.jdem846.projection.ProjectionName;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;

/**
 * {@code --projection NAME|EPSG:CODE|FILE.prj} and {@code --central-meridian}: the map projection of the picture
 * ({@link io.github.jdem846.projection}).
 */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
final class ProjectionOptions {

    private static final Pattern EPSG = Pattern.compile("(?i)EPSG:(\\d{1,9})");

    @Option(names = "--projection", paramLabel = "NAME|EPSG:CODE|FILE.prj",
            description = "Draw the picture in a map projection: a name (" + "equirectangular, mercator, "
                    + "transverse-mercator, robinson, mollweide, winkel-tripel, hammer, aitoff, wagner-vi), an EPSG "
                    + "code Apache SIS knows offline (e.g. EPSG:3395, EPSG:326xx), or a file holding the WKT of a "
                    + "projected CRS. Shading is done on the DEM's grid first, then warped (bilinear; a gray product's "
                    + "no-data left out); --width/--height size the projected picture.")
    String projection;

    @Option(names = "--central-meridian", paramLabel = "DEGREES",
            description = "Central meridian of a named projection, -180 to 180 (default: 0, or the DEM's middle "
                    + "longitude for transverse-mercator and for a DEM that crosses ±180°).")
    Double centralMeridian;

    /** @return true when {@code --projection} was given */
    boolean given() {
        return projection != null;
    }

    /** Refuses {@code --central-meridian} without {@code --projection}, or out of range. */
    void requireConsistent(CommandSpec spec) {
        if (centralMeridian != null && projection == null) {
            throw Usage.error(spec, "--central-meridian needs --projection");
        }
        if (centralMeridian != null && !(centralMeridian >= -180 && centralMeridian <= 180)) {
            throw Usage.invalid(spec, "the central meridian must be in [-180, 180] degrees, got " + centralMeridian,
                    "--central-meridian");
        }
    }

    /**
     * The projection named, about {@code --central-meridian} or the default for {@code area}.
     *
     * @param area the DEM's longitude/latitude box, when known
     */
    MapProjection projection(CommandSpec spec, Optional<LatLonBox> area) {
        Matcher epsg = EPSG.matcher(projection.strip());
        try {
            if (epsg.matches()) {
                noCentralMeridian(spec);
                return MapProjection.fromEpsg(Integer.parseInt(epsg.group(1)));
            }
            Optional<ProjectionName> name = ProjectionName.of(projection);
            if (name.isPresent()) {
                double cm = centralMeridian != null ? centralMeridian
                        : area.map(a -> ProjectedRender.defaultCentralMeridian(name.get(), a)).orElse(0.0);
                return MapProjection.named(name.get(), cm);
            }
            Path file = Path.of(projection);
            if (Files.isRegularFile(file)) {
                noCentralMeridian(spec);
                return MapProjection.fromWkt(Files.readString(file));
            }
        } catch (IllegalArgumentException | IOException e) {
            throw Usage.invalid(spec, "'" + projection + "': " + e.getMessage(), "--projection");
        }
        throw Usage.invalid(spec, "'" + projection + "' is not a projection name ("
                + ProjectionName.list() + "), an EPSG:code or a .prj file", "--projection");
    }

    private void noCentralMeridian(CommandSpec spec) {
        if (centralMeridian != null) {
            throw Usage.error(spec, "--central-meridian applies to a named projection, not to "
                    + projection.toLowerCase(Locale.ROOT));
        }
    }
}
