package io.github.jdem846.spark;

import java.net.URI;
import org.apache.hadoop.fs.Path;
import org.apache.hadoop.fs.RawLocalFileSystem;

/**
 * The local disk under another URI scheme, {@code remotelike:///…}, registered with Hadoop as
 * {@code fs.remotelike.impl}: stands in for HDFS or S3A, so that tests take the path a remote input takes (globbed by
 * Hadoop, copied to the executors by Spark) and write through Hadoop to a non-{@code file:} output.
 */
public class RemoteLikeFileSystem extends RawLocalFileSystem {

    static final String SCHEME = "remotelike";

    @Override
    public URI getUri() {
        return URI.create(SCHEME + ":///");
    }

    @Override
    public String getScheme() {
        return SCHEME;
    }

    @Override
    public Path getWorkingDirectory() {
        return ours(super.getWorkingDirectory());
    }

    @Override
    public Path getHomeDirectory() {
        return ours(super.getHomeDirectory());
    }

    private static Path ours(Path local) {
        return local == null ? null : new Path(SCHEME + "://" + local.toUri().getPath());
    }
}
