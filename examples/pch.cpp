// An empty file: the target that precompiles the headers the feature programs share.
