package io.github.jdem846.output;

import io.github.jdem846.internal.SisLoggers;
import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
import java.time.ZoneOffset;
import java.util.Locale;
import java.util.Optional;
import org.apache.sis.io.wkt.Convention;
import org.apache.sis.io.wkt.WKTFormat;
import org.opengis.referencing.crs.CoordinateReferenceSystem;

/**
 * The text of a {@code .prj} sidecar: the CRS as one line of WKT 1 in the "common units" dialect that ESRI
 * software and GDAL read (angular units in degrees, {@link Convention#WKT1_COMMON_UNITS}), formatted by Apache SIS.
 */
final class EsriPrj {

    static {
        SisLoggers.quiet(); // SIS's routine warnings off stderr, unless the application configured them
    }

    private EsriPrj() {
    }

    /**
     * The outcome: the WKT and the SIS CRS it was made from when the CRS could be written, else a note for the
     * user.
     */
    record Result(Optional<String> wkt, CoordinateReferenceSystem crs, String notice) {

        static Result omitted(String notice) {
            return new Result(Optional.empty(), null, notice);
        }
    }

    /**
     * The WKT of {@code crs}: from its SIS object, else from its EPSG code when SIS can build that CRS offline;
     * empty with a notice when neither is available.
     */
    static Result of(CrsInfo crs) {
        CoordinateReferenceSystem sis = crs.sisCrs();
        if (sis == null && crs.epsg() != null) {
            // east–north axis order, as every CRS a reader resolves (CrsResolver)
            sis = CrsResolver.fromEpsg(crs.epsg()).map(CrsInfo::sisCrs).orElse(null);
            if (sis == null) {
                return Result.omitted("no .prj written: EPSG:" + crs.epsg()
                        + " has no definition available offline");
            }
        }
        if (sis == null) {
            return Result.omitted("no .prj written: the CRS is unknown"
                    + (crs.name() != null ? " (only its name, '" + crs.name() + "', is known)" : ""));
        }
        WKTFormat format = new WKTFormat(Locale.ROOT, ZoneOffset.UTC);
        format.setConvention(Convention.WKT1_COMMON_UNITS);
        format.setIndentation(WKTFormat.SINGLE_LINE);
        String wkt;
        try {
            wkt = format.format(sis);
        } catch (RuntimeException e) { // UnformattableObjectException: no WKT 1 form
            return Result.omitted("no .prj written: the CRS '" + sis.getName().getCode()
                    + "' has no WKT 1 form (" + e.getMessage() + ")");
        }
        // format.getWarnings() is not reported: WKT 1 "common units" departs from the standard by design, and SIS
        // warns about every EPSG parameter name it replaces by its OGC alias.
        return new Result(Optional.of(wkt), sis, null);
    }
}
