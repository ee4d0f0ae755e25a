package io.github.jdem846.cli;

import io.github.jdem846.geo.LatLon;
import io.github.jdem846.job.Sun;
import io.github.jdem846.sun.ZonedTimeParser;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * The light: {@code --sun-azimuth}/{@code --sun-elevation} (the original's defaults 320° and 25°), or the real sun
 * at {@code --sun-time}, seen from the DEM's centre, from {@code --sun-at}, or per tile.
 */
@Command(addMethodSubcommands = false) // no command methods to look for: a quicker start
public final class SunOptions {

    @Spec(Spec.Target.MIXEE)
    CommandSpec command;

    @Option(names = "--sun-time", paramLabel = "TIME", converter = Converters.Time.class,
            description = "Compute the sun for this instant instead (ISO-8601 with offset or zone, e.g. "
                    + "2024-06-21T05:30+02:00 or 2024-06-21T05:30[Europe/Luxembourg]), seen from the DEM's centre.")
    String time;

    @Option(names = "--sun-at", paramLabel = "LAT,LON", converter = SunCommand.LatLonConverter.class,
            description = "With --sun-time: the place to compute the sun for, latitude -90 to 90 and longitude -180 "
                    + "to 180 in degrees (needed when the DEM's CRS is unknown).")
    LatLon place;

    @Option(names = "--sun-per-tile",
            description = "With --sun-time: recompute the sun for every tile from its own latitude/longitude.")
    boolean perTile;

    @Option(names = "--twilight",
            description = "With --sun-time: the original's twilight fade, darkening the scene linearly from zenith "
                    + "90° to 108° (civil to astronomical twilight).")
    boolean twilight;

    @Option(names = {"--sun-azimuth", "--azimuth", "-az"}, paramLabel = "DEG", converter = Converters.Azimuth.class,
            description = "Sun azimuth, degrees clockwise from north: any finite number, reduced to [0, 360). "
                    + "Default: 320.")
    Double azimuth;

    @Option(names = {"--sun-elevation", "--altitude", "-alt"}, paramLabel = "DEG",
            converter = Converters.Elevation.class,
            description = "Sun elevation above the horizon in degrees, -90 to 90 (at 0 or below, cast shadows "
                    + "cover every cell). Default: 25.")
    Double elevation;

    /**
     * Refuses options that do not go together: a sun by time and by angles, or the sun-by-time options without
     * {@code --sun-time}; and a sun by time on a body other than the Earth.
     *
     * @throws picocli.CommandLine.ParameterException naming the options
     */
    void requireConsistent(BodyOptions body) {
        if (time == null && (place != null || perTile || twilight)) {
            throw Usage.error(command, "--sun-at, --sun-per-tile and --twilight need --sun-time");
        }
        if (time != null && (azimuth != null || elevation != null)) {
            throw Usage.error(command, "give either --sun-time or --sun-azimuth/--sun-elevation, not both");
        }
        if (time != null) {
            body.bodyForSunByTime();
        }
    }

    /** True when the sun is given by date and time. */
    boolean byTime() {
        return time != null;
    }

    /** The light these options describe; they must be consistent ({@link #requireConsistent}). */
    Sun sun() {
        if (time == null) {
            return Sun.fixed(azimuth != null ? azimuth : 320, elevation != null ? elevation : 25);
        }
        return Sun.at(ZonedTimeParser.parse(time)).seenFrom(place).perTile(perTile).withTwilight(twilight);
    }

    /** The {@code --sun-time} text as given, or null. */
    String time() {
        return time;
    }
}
