package io.github.jdem846.cli;

import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
import io.github.jdem846.geo.LatLon;
import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.LoadedDem;
import io.github.jdem846.raster.ElevationStatistics;
import io.github.jdem846.sun.Body;
import io.github.jdem846.sun.Observer;
import io.github.jdem846.sun.SunLightField;
import io.github.jdem846.sun.SunPosition;
import io.github.jdem846.sun.ZonedTimeParser;
import io.github.jdem846.io.DemInput;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code jdem846 info [FILE...] [--json]}: format, size, data type, CRS, extent (native and latitude/longitude),
 * cell size (native and metres), no-data and elevation range of a DEM file, or of the bundled sample when no
 * FILE is given; of several files, the mosaic they make, with the list of files. Elevations are streamed, so files
 * larger than the heap can be described.
 */
@Command(name = "info", addMethodSubcommands = false,
        mixinStandardHelpOptions = true,
        versionProvider = VersionProvider.class,
        description = "Describe a DEM: format, size, data type, CRS, extent, cell size, no-data, min and max.",
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:described", "1:the file cannot be read (the message says why)", "2:bad usage"})
public final class InfoCommand implements Callable<Integer> {

    @Parameters(arity = "0..*", paramLabel = "FILE",
            description = "GeoTIFF, ESRI GridFloat (.flt), ESRI ASCII grid (.asc), ESRI BIL (.bil), SRTM .hgt or a"
                    + " GDAL .vrt; the bundled sample DEM when omitted. Several files, a directory or a quoted glob"
                    + " ('tiles/*.hgt') are described as the one grid they make (a mosaic).")
    List<String> files;

    @Option(names = "--json", description = "Print one JSON object instead of text.")
    boolean json;

    @Option(names = "--sun-time", paramLabel = "TIME", converter = Converters.Time.class,
            description = "Also give the sun at the DEM's centre at this instant (ISO-8601 with offset or zone).")
    String sunTime;

    @Option(names = "--sun-at", paramLabel = "LAT,LON", converter = SunCommand.LatLonConverter.class,
            description = "With --sun-time: the place, when the DEM's CRS cannot give the centre's latitude/longitude;"
                    + " latitude -90 to 90, longitude -180 to 180.")
    LatLon sunAt;

    @Mixin
    BodyOptions bodyOptions;

    @Mixin
    VerboseOption verbose;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        if (sunAt != null && sunTime == null) {
            throw Usage.error(spec, "--sun-at needs --sun-time");
        }
        Body body = sunTime != null ? bodyOptions.bodyForSunByTime() : bodyOptions.body();
        DemInfo info;
        ElevationStatistics stats;
        InputPaths.Resolved resolved = InputPaths.resolve(spec, files);
        for (String note : resolved.notes()) {
            spec.commandLine().getErr().println("jdem846: note: " + note);
        }
        DemInput input = resolved.input();
        if (input == null) {
            LoadedDem sample = BundledSample.load();
            info = sample.info();
            stats = sample.dem().statistics();
        } else {
            info = DemReader.inspect(input);
            stats = DemReader.statistics(input);
        }
        CrsInfo crs = CrsResolver.complete(info.geometry().crs());
        if (crs != info.geometry().crs()) {
            info = info.withGeometry(info.geometry().withCrs(crs));
        }
        info = info.withDefaultEllipsoid(body.ellipsoid());
        SunPosition sun = null;
        if (sunTime != null) {
            sun = SunLightField.of(info.geometry(), ZonedTimeParser.parse(sunTime), sunAt, 0, Observer.SEA_LEVEL).centralSun();
        }
        InfoReport report = new InfoReport(info, stats, sunTime, sun);
        spec.commandLine().getOut().println(json ? report.toJson() : report.toText());
        spec.commandLine().getOut().flush();
        return 0;
    }
}
