/**
 * Shaded relief from digital elevation models: read a DEM ({@link io.github.jdem846.io.DemReader}), render one
 * picture of it in one call ({@link io.github.jdem846.job.ReliefJob}), or use each stage alone (tint, hillshade,
 * cast shadows, the sun's position).
 *
 * <p>Exported: the packages whose public types a library user handles. Not exported: the format readers
 * ({@code io.geotiff}, {@code io.esri}, {@code io.source}), {@code internal} and {@code parallel} (how stages share a
 * pool and are cancelled). The command line is not part of this module: it is built from its own source root into
 * the self-contained {@code jdem846-cli.jar}. Apache SIS and GeoAPI are read transitively, since
 * {@link io.github.jdem846.geo.CrsInfo#sis()} hands out a GeoAPI {@code CoordinateReferenceSystem}.
 */
// requires-automatic: TwelveMonkeys has no module-info; module: the name ends in digits (jdem846)
@SuppressWarnings({"requires-automatic", "module"})
module io.github.jdem846 {
    exports io.github.jdem846.drape;
    exports io.github.jdem846.geo;
    exports io.github.jdem846.io;
    exports io.github.jdem846.job;
    exports io.github.jdem846.light;
    exports io.github.jdem846.output;
    exports io.github.jdem846.overlay;
    exports io.github.jdem846.projection;
    exports io.github.jdem846.raster;
    exports io.github.jdem846.render;
    exports io.github.jdem846.shade;
    exports io.github.jdem846.shadow;
    exports io.github.jdem846.sun;
    exports io.github.jdem846.tiles;
    exports io.github.jdem846.tint;
    exports io.github.jdem846.view;

    // BufferedImage and RenderedRelief in the API; ImageIO for reading and writing
    requires transitive java.desktop;
    // CRS parsing and WKT; its modules also make GeoAPI (org.opengis.geoapi) and javax.measure readable
    requires transitive org.apache.sis.referencing;
    // GDAL_METADATA and .aux.xml
    requires java.xml;
    // quieting Apache SIS's java.util.logging warnings (internal.SisLoggers)
    requires java.logging;
    // GeoTIFF decoding (automatic modules, named by their Automatic-Module-Name; the reader's superclass is in core)
    requires com.twelvemonkeys.imageio.tiff;
    requires com.twelvemonkeys.imageio.core;
    // vector overlays: JTS geometries (in the overlay API) and its GeoJSON reader
    requires transitive org.locationtech.jts;
    requires org.locationtech.jts.io;
    // feature properties of GeoJSON overlays: the JSON parser JTS's reader brings (named from its jar file)
    requires json.simple;
    // NREL SPA sun positions
    requires net.e175.klaus.solarpositioning;
}
