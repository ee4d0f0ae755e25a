package io.github.jdem846.io.mosaic;

import io.github.jdem846.internal.SisLoggers;
import io.github.jdem846.geo.CrsInfo;
import io.github.jdem846.geo.CrsResolver;
import java.util.Locale;
import java.util.Objects;
import org.apache.sis.util.Utilities;

/**
 * Whether two files' CRSs are the same, as far as their headers tell: the same kind (geographic, projected,
 * unknown), and the same EPSG code when both have one; otherwise the same Apache SIS definition, metadata aside;
 * otherwise the same linear unit, ellipsoid and name. Reprojection is not done here: tiles of different CRSs are
 * refused.
 */
final class CrsMatch {

    static {
        SisLoggers.quiet(); // SIS's routine warnings off stderr, unless the application configured them
    }

    private CrsMatch() {
    }

    static boolean same(CrsInfo a, CrsInfo b) {
        if (a.kind() != b.kind()) {
            return false;
        }
        if (a.epsg() != null && b.epsg() != null) {
            return a.epsg().equals(b.epsg());
        }
        if (a.kind() == CrsInfo.Kind.UNKNOWN && a.sisCrs() == null && b.sisCrs() == null) {
            return Objects.equals(a.epsg(), b.epsg()); // nothing known of either: alike
        }
        CrsInfo ca = CrsResolver.complete(a);
        CrsInfo cb = CrsResolver.complete(b);
        if (ca.sisCrs() != null && cb.sisCrs() != null) {
            return Utilities.equalsIgnoreMetadata(ca.sisCrs(), cb.sisCrs());
        }
        boolean sameUnit = a.kind() != CrsInfo.Kind.PROJECTED
                || Math.abs(a.linearUnitMeters() - b.linearUnitMeters()) <= 1e-12 * a.linearUnitMeters();
        return sameUnit && Objects.equals(a.ellipsoid(), b.ellipsoid())
                && Objects.equals(lower(a.name()), lower(b.name()));
    }

    /** The CRS in a few words, for a message: name, EPSG code, kind. */
    static String describe(CrsInfo crs) {
        if (crs.kind() == CrsInfo.Kind.UNKNOWN && crs.name() == null && crs.epsg() == null) {
            return "no CRS";
        }
        StringBuilder sb = new StringBuilder(crs.name() != null ? "'" + crs.name() + "'" : "an unnamed CRS");
        if (crs.epsg() != null) {
            sb.append(" (EPSG:").append(crs.epsg()).append(')');
        }
        sb.append(switch (crs.kind()) {
            case GEOGRAPHIC -> ", geographic";
            case PROJECTED -> ", projected";
            case UNKNOWN -> ", of unknown units";
        });
        if (crs.assumed()) {
            sb.append(", assumed");
        }
        return sb.toString();
    }

    private static String lower(String s) {
        return s == null ? null : s.toLowerCase(Locale.ROOT);
    }
}
